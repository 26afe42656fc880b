#pragma once
// The frames of Preview path (app/editor/motion_preview.h), rendered at full quality one at a
// time with the editor's renderer: each path frame is what `render` writes for that frame (the
// camera at the path's pose), and on the way its flicker is measured as `measure` does
// (metrics::FlickerMeter over the observer's shadow read-back): F and the per-pixel map. Needs
// the GL context current; no window, so a GL test renders it headless.
#include "metrics/flicker.h"
#include "renderer/image/image_io.h"
#include "renderer/render/measure_pass.h"
#include "renderer/render/renderer.h"
#include "renderer/settings/settings.h"

#include <memory>
#include <optional>
#include <vector>

namespace st::app {

class PathPreviewRender {
public:
    // Renders path frame frames().size() of `path` (its output size is the frames' size; its
    // camera observes the flicker) with `r`, which then holds that frame. After the last frame
    // flicker() and flickerMap() are set.
    void renderNext(Renderer& r, const Settings& path);
    bool done(const Settings& path) const { return int(frames_.size()) >= path.path.frames; }
    const std::vector<Rgba8Image>& frames() const { return frames_; }
    const std::optional<metrics::FlickerReport>& flicker() const { return flicker_; }
    const Rgba8Image& flickerMap() const { return flickerMap_; }  // the observer's pixels, top row first

private:
    std::vector<Rgba8Image> frames_;
    std::unique_ptr<MeasurePass> pass_;
    std::unique_ptr<metrics::FlickerMeter> meter_;
    MeasureSamples first_;  // the observer's samples of frame 0: the meter's points
    std::optional<metrics::FlickerReport> flicker_;
    Rgba8Image flickerMap_;
};

}  // namespace st::app
