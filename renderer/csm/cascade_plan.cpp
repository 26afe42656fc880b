#include "renderer/csm/cascade_plan.h"

#include "renderer/csm/selection.h"
#include "renderer/csm/splits.h"
#include "renderer/settings/split_range.h"

#include <glm/trigonometric.hpp>

namespace st::csm {

CameraParams cameraFromSettings(const CameraSettings& c, float aspect) {
    CameraParams p;
    p.wsPosition = c.position;
    p.wsTarget = c.target;
    p.fovY = glm::radians(c.fovY);
    p.aspect = aspect;
    p.nearPlane = c.nearPlane;
    p.farPlane = c.farPlane;
    return p;
}

std::vector<float> planSplits(const Settings& s, const std::optional<DepthRange>& seen, SplitRange* range) {
    const CascadeSettings& cs = s.cascades;
    SplitParams sp;
    sp.scheme = cs.scheme;
    sp.count = cs.count;
    sp.nearPlane = s.camera.nearPlane;
    sp.farPlane = s.camera.farPlane;
    sp.lambda = cs.lambda;
    sp.manual = cs.manualSplits;
    sp.shadowDistance = cs.shadowDistance;
    if (splitsFollowSeenDepth(cs)) {
        computeSplits(sp);  // the settings' own errors first, named as the user wrote them
        const SplitRange r = fittedSplitRange(sp.nearPlane, splitRangeEnd(sp.farPlane, sp.shadowDistance), seen);
        sp.nearPlane = r.begin;
        sp.farPlane = r.end;
        sp.shadowDistance = 0.0f;
    }
    std::vector<float> z = computeSplits(sp);
    if (range) *range = {z.front(), z.back()};
    return z;
}

bool needsSampleBounds(const CascadeSettings& c) {
    return c.depthBounds == DepthBounds::Fit || c.fit == FitMode::Samples;
}

bool splitsFollowSeenDepth(const CascadeSettings& c) {
    return c.depthBounds == DepthBounds::Fit && c.scheme != SplitScheme::Manual;
}

namespace {
// The camera as an engine job gets it (app/cli/engine_check_command.cpp: the preset's numbers and
// the output's width / height), in double so the float32 stores fall where the engine's do.
Float32Camera float32Camera(const Settings& s, float aspect) {
    const double outputAspect = double(s.output.width) / double(s.output.height);
    return {glm::dvec3(s.camera.position), glm::dvec3(s.camera.target), double(s.camera.fovY),
            float(outputAspect) == aspect ? outputAspect : double(aspect), double(s.camera.nearPlane),
            double(s.camera.farPlane)};
}
}  // namespace

CascadePlan planCascades(const Settings& s, float aspect, const Aabb& wsSceneBounds, const SampleBounds* samples) {
    const CascadeSettings& cs = s.cascades;
    CascadePlan plan;
    plan.camera = cameraFromSettings(s.camera, aspect);
    plan.vsView = viewMatrix(plan.camera);
    plan.csProj = projectionMatrix(plan.camera);
    plan.wsLightDir = lightDirection(s.light.azimuth, s.light.elevation);
    plan.splits = planSplits(s, samples ? samples->depth : std::nullopt, &plan.splitRange);
    plan.depthFitted = samples && splitsFollowSeenDepth(cs);

    FitParams fp;
    fp.fit = cs.fit;
    fp.stabilize = cs.stabilize;
    fp.snap = cs.snap;
    fp.zExtension = cs.zExtension;
    fp.zExtensionDistance = cs.zExtensionDistance;
    fp.lightDepth = cs.lightDepth;
    fp.pancakeToCasters = cs.pancakeToCasters;
    fp.padTexels = s.filter.padding ? filterPaddingTexels(s.filter) : 0;
    fp.wsSceneBounds = wsSceneBounds;
    fp.minFovY = glm::radians(cs.fitFovY);
    fp.wsOrigin = s.origin;
    fp.cameraRelative = cs.cameraRelative;
    fp.sphereAroundCornersMean = cs.sphereCentre == SphereCentre::CornersMean;
    if (cs.sliceCorners == SliceCorners::Float32Inverse) fp.float32Corners = float32Camera(s, aspect);
    plan.storage = planStorage(cs);
    for (int i = 0; i < cs.count; ++i) {
        const auto k = static_cast<std::size_t>(i);
        fp.lsSamples = samples && k < samples->lsCascade.size() ? samples->lsCascade[k] : std::nullopt;
        fp.mapSize = plan.storage.tiles[k].size;  // texel size and snapping per map
        plan.cascades.push_back(fitCascade(plan.camera, plan.splits, i, plan.wsLightDir, fp));
    }
    return plan;
}

}  // namespace st::csm
