#pragma once
// When the editor draws its next frame (issue 21 #2: the idle editor burnt a core redrawing
// panels that showed nothing new). It draws on input, and for a few frames after anything
// changed (ImGui settles hover states and window sizes over the next frames, and the probe's
// read-back is shown the frame after it is made); while something moves by itself (a held key
// or button, the animated sun); and, slowly, while a background job runs whose progress only a
// poll reveals (the Accuracy panel's ground truth, a Sweep child). Otherwise it waits for an
// event and draws nothing. Pure logic: the shell states what happened, the pacer says how long
// to wait; tests feed it made-up frames.
namespace st::app {

// What the frame just drawn saw.
struct FrameActivity {
    bool events = false;      // input or window events (resize, expose, focus) came in for it
    bool changed = false;     // it showed something new: a scene image, a setting, a job's state, a message
    bool animating = false;   // something moves every frame by itself: a held key or button, the animated sun
    bool jobRunning = false;  // a background job runs: its progress shows only when polled
};

class FramePacer {
public:
    static constexpr int kSettleFrames = 3;        // frames drawn after the last event or change
    static constexpr double kJobPollSeconds = 0.25;  // a job's progress, four times a second

    enum class Wait {
        None,     // draw the next frame at once
        Timeout,  // wait for an event at most kJobPollSeconds, then draw
        Event,    // draw nothing until an event comes
    };
    // After each frame: how to wait before the next one.
    Wait after(const FrameActivity& frame);
    // The last after() returned Event: the window shows all there is to show.
    bool idle() const { return idle_; }

private:
    int settle_ = kSettleFrames;  // the first frames place the panels
    bool idle_ = false;
};

}  // namespace st::app
