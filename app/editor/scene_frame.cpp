#include "app/editor/scene_frame.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace st::app {

bool sameFrame(const SceneFrameInputs& x, const SceneFrameInputs& y) {
    const auto orbit = [](const OrbitCamera& o) { return std::tie(o.yawDeg, o.pitchDeg, o.zoom, o.panOffset); };
    return x.sceneKey == y.sceneKey && x.rendererGeneration == y.rendererGeneration && x.live == y.live && x.a == y.a &&
           orbit(x.orbit) == orbit(y.orbit) && x.pipWidth == y.pipWidth && x.pipHeight == y.pipHeight &&
           x.swapped == y.swapped;
}

std::string SceneFrameCache::check(const SceneFrameInputs& now) const {
    if (!held_) return "first frame";
    if (pending_) return "a cascade's update interval is due";
    if (!sameFrame(*held_, now)) return "inputs changed";
    return {};
}

void SceneFrameCache::rendered(const SceneFrameInputs& in, const FrameStats* live, const FrameStats* a) {
    held_ = in;
    pending_ = (live && mapsPending(*live)) || (a && mapsPending(*a));
}

bool mapsPending(const FrameStats& stats) {
    return std::any_of(stats.cascades.begin(), stats.cascades.end(), [](const CascadeStats& c) {
        return !c.redrawn && c.mapReason.find("deferred") != std::string::npos;
    });
}

bool viewMoving(const Settings& previous, const Settings& now) {
    return previous.camera != now.camera || previous.light.azimuth != now.light.azimuth ||
           previous.light.elevation != now.light.elevation;
}

double InteractiveScale::update(bool moving, double lastFrameMs) {
    const bool wasMoving = wasMoving_;
    wasMoving_ = moving;
    if (!moving) return 1.0;
    // Only a moving frame's time says what this scale costs; a still frame's does not.
    if (wasMoving && lastFrameMs > 0.0) {
        const double ratio = targetMs_ / lastFrameMs;
        // The main pass is fragment-bound: its time goes with the pixels, the square of the scale.
        // A band around the target keeps the scale from hunting frame to frame.
        // The image scale's floor still too slow: the maps are what is left to shrink. Full scale
        // with time to spare: the maps grow back first (the scale then comes down to the target).
        if (ratio < 0.85 && scale_ <= kMin && mapDivisor_ == 2) {
            mapDivisor_ = 4;
        } else if (ratio > 1.15 && scale_ >= 1.0 && mapDivisor_ == 4) {
            mapDivisor_ = 2;
        } else if (ratio < 0.85 || ratio > 1.15) {
            const double wanted = std::clamp(scale_ * std::sqrt(ratio), kMin, 1.0);
            scale_ = std::clamp(std::round(wanted / kStep) * kStep, kMin, 1.0);
        }
    }
    return scale_;
}

Settings interactiveMaps(const Settings& s, int divisor) {
    Settings out = s;
    auto smaller = [divisor](int size) { return std::max(256, size / divisor); };
    out.cascades.mapSize = smaller(s.cascades.mapSize);
    for (int& size : out.cascades.mapSizes) size = smaller(size);
    // Cascade i is redrawn at most every i + 1 frames (4 at most), or the preset's interval if
    // longer: about 2 maps a frame instead of 4. A kept map is sampled through the matrix it was
    // drawn with (cascade_cache.h), so shadows stay in place; a far cascade only lags the camera.
    out.cascades.updateInterval.resize(std::size_t(s.cascades.count), 1.0f);
    for (int i = 0; i < s.cascades.count; ++i)
        out.cascades.updateInterval[std::size_t(i)] =
            std::max(out.cascades.updateInterval[std::size_t(i)], float(std::min(i + 1, 4)));
    return out;
}

int scaledSize(int size, double scale) { return std::max(16, int(std::lround(size * scale))); }

}  // namespace st::app
