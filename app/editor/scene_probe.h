#pragma once
// The hover probe's data: the measurement pass's per-pixel read-back of the frame on screen,
// taken once per frame that changed while the mouse rests over the scene, and the readout of one
// pixel of it (ui::ProbeView) with the bias the shaders applied there and, once the Accuracy
// panel has computed it, the ray-cast truth.
#include "metrics/accuracy.h"
#include "renderer/render/measure_pass.h"
#include "renderer/render/measure_samples.h"
#include "renderer/render/renderer.h"
#include "renderer/settings/settings.h"
#include "ui/probe.h"

#include <optional>
#include <vector>

namespace st::app {

// Pure: pixel (x, y) (top-left origin) of `m`. texelWorld: metres per texel by cascade, as the
// shaders' cascade[i].texelWorld; classes: the Accuracy panel's per-pixel classes of this very
// frame, or nullptr. Invalid outside the image or where no surface was drawn.
// depthRange: metres from each cascade's light-box near plane to its far one (a bias in depth units).
ui::ProbeView readProbe(const MeasureSamples& m, int x, int y, const Settings& s, const std::vector<float>& texelWorld,
                        const std::vector<metrics::PixelClass>* classes, const std::vector<float>& depthRange = {});

class SceneProbe {
public:
    SceneProbe() = default;  // the pass is linked on first use, with the GL context current

    // After `r` rendered `s` (s.output = the scene viewport's size): read the frame back if it is
    // wanted and differs from the one already held. Needs the GL context current.
    // `shared`: a pass to read through instead of the probe's own: the editor gives the Accuracy
    // panel's, which draws the same frame's surfaces, so they are kept once (issue 39 #10).
    void update(bool wanted, const Renderer& r, const Settings& s, MeasurePass* shared = nullptr);
    const MeasureSamples* samples() const { return held_ ? &samples_ : nullptr; }

private:
    std::optional<MeasurePass> pass_;
    std::optional<Settings> held_;  // the settings `samples_` show
    MeasureSamples samples_;
};

}  // namespace st::app
