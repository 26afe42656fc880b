#include "app/editor/path_preview_render.h"

#include "metrics/camera_path.h"
#include "metrics/measure_session.h"
#include "metrics/metric_images.h"

namespace st::app {

// measureFlicker's steps (metrics/measure_session.cpp), one frame a call, with each frame's
// image kept: frame 0's full samples fix the meter's points, later frames add their shadows.
void PathPreviewRender::renderNext(Renderer& r, const Settings& path) {
    if (done(path)) return;
    const int frame = int(frames_.size());
    const Settings at = metrics::atPathFrame(path, frame);
    r.render(at);
    frames_.push_back({r.width(), r.height(), r.readRgba8()});
    if (!pass_) pass_ = std::make_unique<MeasurePass>();
    const glm::mat4 observer = metrics::observerViewProj(path);
    if (frame == 0) {
        first_ = pass_->run(r, at, observer);
        meter_ = std::make_unique<metrics::FlickerMeter>(first_, std::vector<std::uint8_t>{}, path.light.intensity);
        meter_->add(first_.shadow);
    } else {
        meter_->add(pass_->runShadowOnly(r, at, observer));
    }
    if (done(path)) {
        flicker_ = meter_->report();
        flickerMap_ = metrics::flickerImage(meter_->hardStdDev(), first_);
    }
}

}  // namespace st::app
