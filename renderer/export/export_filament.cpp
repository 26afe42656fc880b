// Filament: LightManager::ShadowOptions of a directional light, and the View's shadow type.
// Sources (google/filament; docs/engines.md lists the commit and lines): filament/include/filament/
// LightManager.h (ShadowOptions field initialisers and their doc comments), filament/src/
// ShadowMapManager.cpp (splits near + (far or shadowFar - near) x position; normal bias 0.5 x normalBias x
// texel; DEPTH16 maps for PCF), filament/src/ShadowMap.cpp (stable: the slice's bounding sphere, or a
// sphere of radius shadowFar around the camera, snapped, with LiSPSM and caster focusing off; constant
// bias baked into the light camera), shaders/src/common_shadowing.glsl (the normal offset x sin of the
// angle to the light), shaders/src/light_directional.fs (the fade near shadowFar), shaders/src/
// shadowing.fs (ShadowSample_PCF_Low: hardware PCF + 3x3 Gaussian from 4 bilinear taps; VSM).
#include "renderer/export/export_common.h"

#include "renderer/settings/number_text.h"

#include <algorithm>

namespace st::xport {
namespace {

using M = Mapping;

void addCascades(EngineExport& e, const Settings& s, const PresetFacts& f) {
    const CascadeSettings& c = s.cascades;
    e.add("mapSize", c.mapSize, M::Exact, "cascades.mapSize, per cascade");
    e.add("shadowCascades", std::min(c.count, 4), c.count <= 4 ? M::Exact : M::Approximated,
          c.count <= 4 ? "cascades.count" : "Filament has at most 4 cascades (CONFIG_MAX_SHADOW_CASCADES)");
    std::vector<double> pos = fractionsOfRange(f);
    const bool used = !pos.empty();
    const std::vector<double> defaults{0.125, 0.25, 0.5};
    for (size_t i = pos.size(); i < 3; ++i) pos.push_back(defaults[i]);
    e.add("cascadeSplitPositions", numbers(pos), used ? M::Exact : M::NoEquivalent,
          used ? "(z_i - near) / (shadowFar or far - near); entries past count-1 are Filament's defaults"
               : "unused with one cascade; Filament's defaults kept");
    e.add("shadowFar", round6(c.shadowDistance), M::Exact, "cascades.shadowDistance; 0 = the camera far plane");
    // ShadowMap.cpp: stable switches the fit to a sphere (computeFocusParams: the slice's corners' mean and
    // farthest corner, or {camera, shadowFar} when shadowFar > 0), snaps it (snapLightFrustum) and turns off
    // LiSPSM (updateDirectional) and the focus on casters (computeLightFrustumBounds).
    const bool sphere = c.fit == FitMode::Sphere;
    e.add("stable", c.stabilize, M::Approximated,
          !c.stabilize ? "false, as cascades.stabilize: Filament then fits each light frustum to the slice, the receivers "
                         "and the casters, unsnapped"
          : sphere     ? "cascades.stabilize with the sphere fit: Filament's stable fits a sphere around the slice's "
                         "corners (their mean, the farthest as radius; with shadowFar > 0 a sphere of radius shadowFar "
                         "around the camera), snaps it and turns LiSPSM and caster focusing off"
                       : "cascades.stabilize: Filament's stable also swaps the preset's '" +
                             std::string(EnumNames<FitMode>::names[size_t(c.fit)]) +
                             "' fit for a sphere around the slice (radius shadowFar around the camera with shadowFar > 0)");
}

// View::setShadowType (PCF, VSM, DPCF, PCSS) and, for VSM, View::setVsmShadowOptions.
void addFilter(EngineExport& e, const Settings& s) {
    const FilterKind k = s.filter.kind;
    if (isMomentFilter(k)) {
        e.add("View::setShadowType", "VSM", k == FilterKind::Msm ? M::NoEquivalent : M::Approximated,
              k == FilterKind::Msm ? "Filament has no moment shadow maps of four moments; VSM is the nearest"
                                   : "Filament's VSM warps depth by exp(vsmExponent x depth), i.e. EVSM with the "
                                     "positive warp (ELVSM adds the negative one); shadowtune raises p_max to "
                                     "filter.bleedExponent where Filament's lightBleedReduction cuts p_max off");
        e.add("ShadowOptions.vsm.elvsm", k == FilterKind::Evsm4, M::Approximated,
              "the exponential variant with a positive and a negative warp, as evsm4");
        e.add("ShadowOptions.vsm.blurWidth", s.filter.blurRadius > 0 ? 2 * s.filter.blurRadius + 1 : 0, M::Approximated,
              "2 x filter.blurRadius + 1 texels (0 = no blur); the Gaussian's sigma is Filament's own");
        e.add("VsmShadowOptions.mipmapping", s.filter.mipmaps, M::Exact, "filter.mipmaps");
        e.add("VsmShadowOptions.highPrecision", !s.filter.moments16, M::Exact, "32-bit moments unless filter.moments16");
    } else if (k == FilterKind::Pcss) {
        e.add("View::setShadowType", "PCSS", M::Approximated,
              "blocker search and penumbra estimate; Filament sizes the penumbra with setSoftShadowOptions, "
              "shadowtune from light.angularDiameter");
    } else {
        e.add("View::setShadowType", "PCF", k == FilterKind::Hard ? M::NoEquivalent : M::Approximated,
              "PCF (default) samples 16-bit depth maps (DEPTH16; shadowtune's are 32-bit float) with "
              "ShadowSample_PCF_Low, Castano's 4 bilinear taps over 3x3 texels (shadowtune's pcf-tent 3)");
    }
}

void addBias(EngineExport& e, const Settings& s) {
    const BiasSettings& b = s.bias;
    e.add("constantBias", round6(b.constant), M::Exact, "metres, shadows moved away from the light");
    // ShadowMapManager.cpp: normalBias x 0.5 x the cascade's texel ("a half-texel size"); common_shadowing.glsl
    // computeLightSpacePosition moves the receiver along its normal by that x sin of the angle to the light.
    e.add("normalBias", round6(2.0 * b.normalOffset), M::Approximated,
          "2 x bias.normalOffset: Filament moves the receiver along its normal by normalBias x half a texel x the "
          "sine of the angle to the light; shadowtune by bias.normalOffset texels at every angle");
    e.add("polygonOffsetSlope", round6(b.slope), M::Approximated,
          "glPolygonOffset factor: depth slope per texel, ~ texel x tan, shadowtune's slope unit");
    e.add("polygonOffsetConstant", 0.5, M::NoEquivalent,
          "units of depth resolution of Filament's 16-bit PCF maps (DEPTH16); Filament's default kept; shadowtune's "
          "32-bit float maps have no such step");
    addFilter(e, s);
    if (b.receiverPlane && fieldApplies(s, "bias.receiverPlane")) e.add("(receiver-plane bias)", true, M::NoEquivalent, "not a ShadowOptions field");
}

}  // namespace

EngineExport exportFilament(const Settings& s, const PresetFacts& f) {
    EngineExport e{Engine::Filament, "Filament: LightManager::ShadowOptions", {}};
    addCascades(e, s, f);
    addBias(e, s);
    e.add("lispsm", false, M::NoEquivalent,
          "shadowtune does not warp the light projection; Filament's default is true (LiSPSM)");
    e.add("(light box fit)", "tight to the visible casters and receivers",
          s.cascades.fit == FitMode::Cascade ? M::Approximated : M::NoEquivalent,
          "Filament fits each light frustum to the slice and the scene; shadowtune's cascade fit is the slice alone");
    // LightManager.h ShadowOptions: screenSpaceContactShadows (off), stepCount (8) and maxShadowDistance
    // (0.3 m, world units): a screen-space march toward the sun, as filter.contact.
    if (s.filter.contact != ContactShadows::Off) {
        e.add("screenSpaceContactShadows", true, M::Exact, "filter.contact: a screen-space march toward the sun");
        e.add("maxShadowDistance", round6(s.filter.contactLength), M::Approximated,
              "filter.contactLength in metres: how far the march reaches; Filament's thickness is its own");
        e.add("stepCount", std::min(s.filter.contactSteps, 255), M::Exact, "filter.contactSteps (a uint8_t)");
    }
    addKnobsWithoutSetting(
        e, s,
        {.cameraRelative = "not a ShadowOptions field; Filament fits each cascade in world space",
         .fitFovY = "Filament fits each cascade to the camera's current frustum",
         .contact = ""});
    // light_directional.fs with PerViewUniforms.cpp: with shadowFar > 0 the shadow fades as
    // saturate(5 - 5 z^2 / shadowFar^2) in view depth z, from 0.894 x shadowFar to shadowFar; none without.
    const bool fades = s.cascades.shadowDistance > 0.0f;
    if (fades && s.cascades.fadeBand > 0.0f)
        e.add("(far fade)", round6(s.cascades.fadeBand), M::Approximated,
              "cascades.fadeBand: Filament always fades from 0.894 x shadowFar to shadowFar, in squared view depth, "
              "and has no setting for the band");
    else if (fades)
        e.add("(far fade)", 0.0, M::NoEquivalent,
              "Filament fades from 0.894 x shadowFar to shadowFar whenever shadowFar > 0; the preset has no "
              "cascades.fadeBand");
    addShadowtuneOnly(e, s, fades);
    return e;
}

}  // namespace st::xport
