// three.js CSM addon: the options of new CSM({...}).
// Source (mrdoob/three.js): examples/jsm/csm/CSM.js (constructor defaults; _getBreaks: breaks are
// split depths / far with far = min(camera.far, maxFar), practical mode = lerp(uniform, log, 0.5);
// update(): light box sized by the slice diagonal, centre snapped to texels, light placed
// lightMargin beyond the slice); src/renderers/shaders/ShaderChunk/shadowmap_pars_fragment.glsl.js
// (shadowCoord.z += shadowBias, in the shadow camera's normalised depth).
#include "renderer/export/export_common.h"

#include "renderer/settings/number_text.h"

namespace st::xport {
namespace {

using M = Mapping;

constexpr double kLightNear = 1.0, kLightFar = 2000.0;  // CSM.js lightNear, lightFar defaults

void addSplits(EngineExport& e, const Settings& s, const PresetFacts& f) {
    const CascadeSettings& c = s.cascades;
    e.add("cascades", c.count, M::Exact, "cascades.count");
    // maxFar only limits camera.far: CSM.js's default 100000 means "the camera far plane".
    e.add("maxFar", c.shadowDistance > 0.0f ? round6(c.shadowDistance) : 100000.0, M::Exact,
          c.shadowDistance > 0.0f ? "cascades.shadowDistance" : "shadows to the camera far plane (CSM.js default)");
    const bool practical05 = c.scheme == SplitScheme::Practical && c.lambda == 0.5f;
    const bool named = practical05 || c.scheme == SplitScheme::Uniform || c.scheme == SplitScheme::Logarithmic;
    const char* mode = practical05 ? "practical" : c.scheme == SplitScheme::Uniform ? "uniform"
                                                 : c.scheme == SplitScheme::Logarithmic ? "logarithmic" : "custom";
    e.add("mode", mode, M::Exact,
          named ? "the same formula as shadowtune's (practical is lambda 0.5)"
                : "customSplitsCallback pushes the breaks below (shadowtune's manual or practical lambda != 0.5)");
    std::vector<double> breaks = fractionsOfEnd(f);
    breaks.push_back(1.0);
    e.add("breaks", numbers(breaks), M::Exact, "split depth / far: what customSplitsCallback pushes");
    e.add("shadowMapSize", c.mapSize, M::Exact, "cascades.mapSize, per cascade light");
}

void addFitAndBias(EngineExport& e, const Settings& s) {
    const CascadeSettings& c = s.cascades;
    const bool dist = c.zExtension == ZExtension::Distance;
    e.add("lightMargin", dist ? round6(c.zExtensionDistance + kLightNear) : 200.0, dist ? M::Approximated : M::NoEquivalent,
          dist ? "zExtensionDistance + lightNear 1: the box reaches that far toward the sun beyond the slice"
               : "only the distance z extension has an equivalent; CSM.js's default kept");
    e.add("lightFar", kLightFar, M::NoEquivalent,
          "the box reaches lightFar - lightMargin beyond the slice away from the sun; shadowtune stops at the slice");
    const double depthRange = kLightFar - kLightNear;
    e.add("shadowBias", round6(-s.bias.constant / depthRange) + 0.0,  // + 0.0: no "-0"
          M::Approximated,
          "-bias.constant / (lightFar - lightNear) = normalised depth; three.js adds it to the receiver's depth, so "
          "negative moves toward the light (CSM.js's default +1e-6 moves 2 mm away: shadowtune cannot go below 0)");
    e.add("fade", c.blendBand > 0.0f, M::Approximated, "CSM.js fades over a fixed margin, not blendBand's fraction");
    const FilterKind k = s.filter.kind;
    if (isMomentFilter(k)) {
        e.add("renderer.shadowMap.type", "VSMShadowMap", k == FilterKind::Vsm ? M::Approximated : M::NoEquivalent,
              k == FilterKind::Vsm ? "a two-moment map blurred by three.js; no light-bleeding reduction"
                                   : "three.js's only moment map is VSM; " + filterKindText(s) + " has no equivalent");
        e.add("light.shadow.radius", s.filter.blurRadius, M::Approximated,
              "filter.blurRadius: three.js's VSM blur radius in texels (its kernel is its own, blurSamples taps)");
    } else {
        e.add("renderer.shadowMap.type", k == FilterKind::Hard ? "BasicShadowMap" : "PCFShadowMap",
              k == FilterKind::Hard ? M::Exact : k == FilterKind::Pcss ? M::NoEquivalent : M::Approximated,
              k == FilterKind::Hard   ? "one unfiltered tap"
              : k == FilterKind::Pcss ? "three.js has no PCSS map type; PCF is the nearest"
                                      : "a fixed ring of compared taps within shadowRadius texels");
    }
    e.add("(cascade fit)", "diagonal-sized box, texel-snapped", c.fit == FitMode::Sphere && c.stabilize
                                                                    ? M::Approximated : M::NoEquivalent,
          "CSM.js sizes each box by the slice's larger diagonal and snaps its centre to texels");
    if (s.bias.slope > 0.0f) e.add("(slope bias)", round6(s.bias.slope), M::NoEquivalent, "three.js has none");
    if (s.bias.normalOffset > 0.0f)
        e.add("light.shadow.normalBias", round6(s.bias.normalOffset), M::NoEquivalent,
              "three.js's normalBias is in world units, not texels, and CSM.js does not set it");
}

}  // namespace

EngineExport exportThreeJs(const Settings& s, const PresetFacts& f) {
    EngineExport e{Engine::ThreeJs, "three.js: CSM addon (examples/jsm/csm/CSM.js)", {}};
    addSplits(e, s, f);
    addFitAndBias(e, s);
    addKnobsWithoutSetting(
        e, s,
        {.cameraRelative = "CSM.js fits its light boxes in world space, in float32",
         .fitFovY = "CSM.js fits the camera's current frustum (updateFrustums() after a FOV change)",
         .contact = "three.js has no screen-space contact shadows"});
    addShadowtuneOnly(e, s, false);
    return e;
}

}  // namespace st::xport
