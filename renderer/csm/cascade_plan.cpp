#include "renderer/csm/cascade_plan.h"

#include "renderer/csm/selection.h"
#include "renderer/csm/splits.h"

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

CascadePlan planCascades(const Settings& s, float aspect, const Aabb& wsSceneBounds) {
    const CascadeSettings& cs = s.cascades;
    CascadePlan plan;
    plan.camera = cameraFromSettings(s.camera, aspect);
    plan.vsView = viewMatrix(plan.camera);
    plan.csProj = projectionMatrix(plan.camera);
    plan.wsLightDir = lightDirection(s.light.azimuth, s.light.elevation);

    SplitParams sp;
    sp.scheme = cs.scheme;
    sp.count = cs.count;
    sp.nearPlane = s.camera.nearPlane;
    sp.farPlane = s.camera.farPlane;
    sp.lambda = cs.lambda;
    sp.manual = cs.manualSplits;
    sp.shadowDistance = cs.shadowDistance;
    plan.splits = computeSplits(sp);

    FitParams fp;
    fp.fit = cs.fit;
    fp.stabilize = cs.stabilize;
    fp.zExtension = cs.zExtension;
    fp.zExtensionDistance = cs.zExtensionDistance;
    fp.mapSize = cs.mapSize;
    fp.padTexels = s.filter.padding ? filterPaddingTexels(s.filter) : 0;
    fp.wsSceneBounds = wsSceneBounds;
    for (int i = 0; i < cs.count; ++i)
        plan.cascades.push_back(fitCascade(plan.camera, plan.splits, i, plan.wsLightDir, fp));
    return plan;
}

}  // namespace st::csm
