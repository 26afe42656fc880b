#include "app/editor/scene_probe.h"

#include "metrics/measure_session.h"

#include <algorithm>
#include <cmath>

namespace st::app {
namespace {

// shaders/shadow_sampling.glsl, tanToLight: tan of the angle to the sun, kept finite.
float tanToLight(float nDotL) {
    const float cosT = std::clamp(nDotL, 1e-3f, 1.0f);
    return std::min(std::sqrt(1.0f - cosT * cosT) / cosT, 10.0f);
}

// The truth a pixel class implies: the map's answer, or its opposite where the class says it
// was wrong.
int truthOf(metrics::PixelClass c) {
    using C = metrics::PixelClass;
    switch (c) {
    case C::CorrectLit:
    case C::FalseShadowEdge:
    case C::FalseShadowGross: return 1;
    case C::CorrectShadow:
    case C::FalseLightEdge:
    case C::FalseLightGross: return 0;
    case C::NoSurface:
    case C::FacingAway:
    case C::Terminator: return -1;
    }
    return -1;
}

}  // namespace

ui::ProbeView readProbe(const MeasureSamples& m, int x, int y, const Settings& s, const std::vector<float>& texelWorld,
                        const std::vector<metrics::PixelClass>* classes, const std::vector<float>& depthRange) {
    ui::ProbeView p;
    p.x = x;
    p.y = y;
    if (x < 0 || y < 0 || x >= m.width || y >= m.height) return p;
    const std::size_t i = std::size_t(y) * std::size_t(m.width) + std::size_t(x);
    if (!m.covered(i)) return p;
    p.valid = true;
    p.cascade = m.cascade(i);
    p.hardResult = m.shadow[i].x;
    p.filteredFactor = m.shadow[i].y;
    p.pixelsPerTexel = m.shadow[i].w;
    p.nDotL = m.normal[i].w;
    p.sunFacing = m.receiver(i);
    if (p.cascade >= 0 && std::size_t(p.cascade) < texelWorld.size()) {
        // shaders/shadow_sampling.glsl: biasedDepth (constant + slope x texel x tan) and
        // shadowCoord (normal offset in texels of the cascade).
        p.texelWorldSize = texelWorld[std::size_t(p.cascade)];
        const std::size_t c = std::size_t(p.cascade);
        const CascadeBiasMetres bias =
            cascadeBiasMetres(s.bias, p.cascade, p.texelWorldSize, c < depthRange.size() ? depthRange[c] : 0.0f);
        p.constantBias = bias.constant;
        p.slopeBias = bias.slopePerTan * tanToLight(p.nDotL);
        p.offsetOnCasters = s.bias.normalOffsetSide == NormalOffsetSide::CasterSin;
        p.normalOffset = p.offsetOnCasters ? bias.casterOffset : bias.receiverOffset;
    }
    if (classes && classes->size() == m.size()) p.truth = truthOf((*classes)[i]);
    return p;
}

void SceneProbe::update(bool wanted, const Renderer& r, const Settings& s, MeasurePass* shared) {
    if (!wanted || (held_ && *held_ == s)) return;
    if (!shared && !pass_) pass_.emplace();
    samples_ = (shared ? *shared : *pass_).run(r, s, metrics::observerViewProj(s));
    held_ = s;
}

}  // namespace st::app
