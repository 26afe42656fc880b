#pragma once
// Preview path (issue 21 #3): shimmer judged at full quality. The preset's camera path, or the
// user's last camera move when the preset has none, is rendered at the viewport's full size a
// few frames per editor frame (the panels stay responsive and show the progress), then played as
// a loop. Its flicker is measured on the way as `measure` measures it (the path moves the cascade
// camera, the editor's camera observes): F, and the per-pixel flicker map the overlay shows.
// The state lives here, with no GL; the viewport renders the frames (app/editor/path_preview_render.h).
#include "renderer/settings/settings.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace st::app {

// The user's last camera move: the poses of the frames in which the camera moved, from the first
// after a pause of kPauseSeconds outside a drag (a drag is one move, however slow its frames),
// thinned to at most kMaxPoses (every other pose dropped, and then every other frame recorded).
class CameraPathRecorder {
public:
    static constexpr std::size_t kMaxPoses = 48;
    static constexpr double kPauseSeconds = 1.0;
    // Once per editor frame, at its time; `held`: a fly, pan or orbit drag's button is down.
    void frame(const CameraSettings& camera, double seconds, bool held);
    const std::vector<CameraKeyframe>& poses() const { return poses_; }

private:
    std::vector<CameraKeyframe> poses_;
    std::optional<CameraSettings> last_;
    std::optional<double> lastMove_;  // when the camera last moved
    bool dragging_ = false;           // that move was a drag still held
    int stride_ = 1;   // record every stride-th moving frame
    int skipped_ = 0;  // moving frames since the last recorded one
};

// `s` with the path a preview plays: the preset's when it has frames, else the recorded poses,
// one frame each (a single pose is no move). nullopt when there is neither. `source` says which.
std::optional<Settings> previewPath(const Settings& s, const std::vector<CameraKeyframe>& recorded, std::string& source);

class MotionPreview {
public:
    enum class State { Off, Rendering, Playing };
    static constexpr double kPlayFps = 12.0;  // the loop's frames a second

    void start(Settings path, std::string source);  // path.path.frames > 0
    void stop();
    void frameRendered();  // the viewport rendered the next frame; the last one starts the loop
    void flickerMeasured(double flipRate) { flipRate_ = flipRate; }
    void toggleOverlay() { overlay_ = !overlay_; }
    // The frame of the loop `seconds` after it started.
    int frameAt(double seconds) const;

    State state() const { return state_; }
    bool active() const { return state_ != State::Off; }
    int rendered() const { return rendered_; }
    int frames() const { return path_.path.frames; }
    const Settings& path() const { return path_; }  // the observer is its camera
    bool overlay() const { return overlay_; }
    std::uint64_t generation() const { return generation_; }  // a new start: older frames are void
    // "Preview path (the preset's path, 16 frames): rendering 5 of 16" / "...: playing, F 0.412 %".
    std::string line() const;

private:
    State state_ = State::Off;
    Settings path_;
    std::string source_;
    int rendered_ = 0;
    std::optional<double> flipRate_;
    bool overlay_ = false;
    std::uint64_t generation_ = 0;
};

}  // namespace st::app
