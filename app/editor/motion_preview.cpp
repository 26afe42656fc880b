#include "app/editor/motion_preview.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace st::app {

void CameraPathRecorder::frame(const CameraSettings& camera, double seconds, bool held) {
    const bool moved = last_ && !(*last_ == camera);
    last_ = camera;
    if (!moved) {
        dragging_ = dragging_ && held;
        return;
    }
    // The same drag however slow its frames (a full-quality frame may take a second here).
    const bool sameDrag = dragging_ && held;
    dragging_ = held;
    if (!sameDrag && (!lastMove_ || seconds - *lastMove_ > kPauseSeconds)) {  // a new move replaces the last one
        poses_.clear();
        stride_ = 1, skipped_ = 0;
    }
    lastMove_ = seconds;
    if (++skipped_ < stride_) return;
    skipped_ = 0;
    poses_.push_back({camera.position, camera.target, camera.fovY});
    if (poses_.size() > kMaxPoses) {
        std::vector<CameraKeyframe> kept;
        for (std::size_t i = 0; i < poses_.size(); i += 2) kept.push_back(poses_[i]);
        poses_ = std::move(kept);
        stride_ *= 2;
    }
}

std::optional<Settings> previewPath(const Settings& s, const std::vector<CameraKeyframe>& recorded, std::string& source) {
    Settings out = s;
    if (s.path.frames > 0 && !s.path.keyframes.empty()) {
        source = "the preset's path";
        return out;
    }
    if (recorded.size() < 2) return std::nullopt;
    out.path.keyframes = recorded;
    out.path.frames = int(recorded.size());
    source = "your last camera move";
    return out;
}

void MotionPreview::start(Settings path, std::string source) {
    state_ = State::Rendering;
    path_ = std::move(path);
    source_ = std::move(source);
    rendered_ = 0;
    flipRate_.reset();
    ++generation_;
}

// Stopping a preview that is off changes nothing: every camera move stops the preview, and a new
// generation each frame made the viewport forget the previous frame, so a moving camera never
// counted as moving (issue 39 #1: orbit and fly at full scale, 1.4 fps on truck-town).
void MotionPreview::stop() {
    if (state_ == State::Off) return;
    state_ = State::Off;
    ++generation_;
}

void MotionPreview::frameRendered() {
    if (state_ != State::Rendering) return;
    if (++rendered_ >= frames()) state_ = State::Playing;
}

int MotionPreview::frameAt(double seconds) const {
    if (frames() <= 0) return 0;
    return int(std::floor(std::max(0.0, seconds) * kPlayFps)) % frames();
}

std::string MotionPreview::line() const {
    if (state_ == State::Off) return {};
    std::string out = "Preview path (" + source_ + ", " + std::to_string(frames()) + " frames at full quality): ";
    if (state_ == State::Rendering) return out + "rendering " + std::to_string(rendered_) + " of " + std::to_string(frames());
    out += "playing";
    if (flipRate_) {
        char f[64];
        std::snprintf(f, sizeof f, ", flicker F %.3f %% (measure's, from this camera)", 100.0 * *flipRate_);
        out += f;
    }
    return out + (overlay_ ? "; the overlay shows each pixel's flicker" : "");
}

}  // namespace st::app
