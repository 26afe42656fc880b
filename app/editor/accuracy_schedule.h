#pragma once
// When the editor computes the Accuracy panel: once the measured frame (camera, settings, window
// size) has stayed the same for a moment. Ground truth takes seconds, so it is not started while
// the user is still flying or dragging a slider; any change cancels the job in flight and drops
// the figures on screen, which no longer describe the frame. Pure logic: times and change events
// come in, actions go out, so tests feed it made-up times.
namespace st::app {

class AccuracySchedule {
public:
    enum class State { Settling, Computing, Done, Failed };
    enum class Action { None, Start, Cancel };

    explicit AccuracySchedule(double settleSeconds = 0.4) : settleSeconds_(settleSeconds) {}

    // Once per frame, `now` in seconds. `changed`: the frame differs from the previous one (or
    // the figures are not wanted). Start: read the frame back and submit it. Cancel: the job in
    // flight describes an older frame, cancel it.
    Action update(double now, bool changed);

    // The job started by the last Start ended (its result is current: results of cancelled
    // jobs never arrive).
    void finished(bool ok);

    State state() const { return state_; }
    double settleSeconds() const { return settleSeconds_; }

private:
    double settleSeconds_;
    State state_ = State::Settling;
    bool haveFrame_ = false;  // stillSince_ is set
    double stillSince_ = 0.0;
};

}  // namespace st::app
