#include "metrics/map_warnings.h"

#include "renderer/csm/z_extension_audit.h"

#include <algorithm>
#include <cstdio>

namespace st::metrics {
namespace {

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, v >= 10.0 ? "%.0f" : "%.2g", v);
    return text;
}

std::string metres(float v) { return csm::formatMetres(v) + " m"; }

// The likeliest reason a cascade's texels are too coarse for its pixels, as a setting to change.
constexpr int kLargestMap = 8192;  // the field table's limit of cascades.mapSize

// The value to try, then the one set: "(cascades.count 5; it is 4)". Naming only the current value
// read as the advice ("a larger cascades.mapSize (512)" for a map already of 512).
std::string moreCascades(const CascadeSettings& c) {
    return "more cascades (cascades.count " + std::to_string(c.count + 1) + "; it is " + std::to_string(c.count) + ")";
}
std::string largerMap(const CascadeSettings& c) {
    return "a larger cascades.mapSize (" + std::to_string(c.mapSize * 2) + "; it is " + std::to_string(c.mapSize) + ")";
}

std::string likelyFix(const Settings& s, const FrameStats& stats, std::optional<float> farthestSeen) {
    const CascadeSettings& c = s.cascades;
    const bool fitted = c.depthBounds == DepthBounds::Fit && c.scheme != SplitScheme::Manual;
    // The splits run well past what is seen: most of the range (and the map) goes to nothing.
    if (!fitted && farthestSeen && stats.splitEnd > 1.5f * *farthestSeen)
        return "cascades.depthBounds \"fit\" or cascades.shadowDistance " + metres(*farthestSeen) +
               " (the splits run to " + metres(stats.splitEnd) + ", the farthest surface seen is at " +
               metres(*farthestSeen) + ")";
    if (c.scheme == SplitScheme::Uniform || (c.scheme == SplitScheme::Practical && c.lambda < 0.9f))
        return "a higher lambda (cascades.lambda " + number(c.scheme == SplitScheme::Uniform ? 0.0 : c.lambda) +
               ", scheme \"practical\"), so the near cascades get a shorter slice";
    if (!fitted && c.scheme != SplitScheme::Manual) return "cascades.depthBounds \"fit\"";
    if (c.count < kMaxCascades) return moreCascades(c);
    if (c.mapSize < kLargestMap) return largerMap(c);
    return "a shorter cascades.shadowDistance (the last cascade ends at " + metres(stats.splitEnd) + ")";
}

// A texel too large for its own sake (a far cascade spread over a long slice): a shorter range
// or more texels, not a higher lambda (which lengthens the far slices).
std::string texelFix(const Settings& s, const FrameStats& stats, std::optional<float> farthestSeen, std::size_t cascade) {
    const CascadeSettings& c = s.cascades;
    const bool fitted = c.depthBounds == DepthBounds::Fit && c.scheme != SplitScheme::Manual;
    if (!fitted && farthestSeen && stats.splitEnd > 1.5f * *farthestSeen) return likelyFix(s, stats, farthestSeen);
    const std::string map = c.mapSize < kLargestMap ? " or " + largerMap(c) : "";
    if (cascade + 1 == stats.cascades.size())
        return "a shorter cascades.shadowDistance (the last cascade ends at " + metres(stats.splitEnd) + ")" + map;
    if (c.count < kMaxCascades) return moreCascades(c) + map;
    return map.empty() ? "a shorter cascades.shadowDistance" : map.substr(4);
}

}  // namespace

std::optional<float> farthestSampleDepth(const MeasureSamples& samples, const glm::mat4& vsView) {
    std::optional<float> far;
    for (std::size_t i = 0; i < samples.size(); ++i) {
        if (!samples.covered(i)) continue;
        const float d = -(vsView * glm::vec4(glm::vec3(samples.position[i]), 1.0f)).z;
        far = far ? std::max(*far, d) : d;
    }
    return far;
}

std::vector<std::string> wastedMapWarnings(const Settings& s, const FrameStats& stats, const DensityReport& density,
                                           std::optional<float> farthestSeen, const MapWarningLimits& limits) {
    std::vector<std::string> out;
    const std::size_t n = std::min(stats.cascades.size(), density.cascades.size());
    for (std::size_t i = 0; i < n; ++i) {
        const DensityStats& d = density.cascades[i];
        if (d.pixels == 0) continue;
        const std::string cascade = "cascade " + std::to_string(i) + ": ";
        const float texel = stats.cascades[i].texelWorldSize;
        if (d.median > limits.maxPixelsPerTexel)
            out.push_back(cascade + "median " + number(d.median) + " screen pixels per shadow texel (limit " +
                          number(limits.maxPixelsPerTexel) + "); likely fix: " + likelyFix(s, stats, farthestSeen));
        else if (texel > limits.maxTexelMetres)
            out.push_back(cascade + "texel " + metres(texel) + " is larger than " + metres(limits.maxTexelMetres) +
                          "; likely fix: " + texelFix(s, stats, farthestSeen, i));
    }
    return out;
}

std::vector<std::string> zExtensionWarnings(const FrameStats& stats) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < stats.cascades.size(); ++i) {
        const CascadeStats& c = stats.cascades[i];
        if (!c.zExtensionCuts) continue;
        out.push_back(csm::zExtensionWarning(int(i), {c.zExtensionUsed, c.zExtensionMinimal, true}));
    }
    return out;
}

}  // namespace st::metrics
