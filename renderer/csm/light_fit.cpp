#include "renderer/csm/light_fit.h"

#include "renderer/csm/error_text.h"
#include "renderer/csm/frustum.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace st::csm {
namespace {

void validateSplits(std::span<const float> splits, int index) {
    if (splits.size() < 2) fail("splits must hold at least 2 values, got " + str(splits.size()));
    const int count = static_cast<int>(splits.size()) - 1;
    if (index < 0 || index >= count)
        fail("index must be in 0.." + str(count - 1) + ", got " + str(index));
    const float a = splits[static_cast<std::size_t>(index)];
    const float b = splits[static_cast<std::size_t>(index) + 1];
    if (!(a >= 0.0f) || !(a < b) || !std::isfinite(b))
        fail("splits[" + str(index) + "] (" + str(a) + ") must be >= 0 and less than splits[" +
             str(index + 1) + "] (" + str(b) + ")");
}

void validateFit(const FitParams& p) {
    if (p.mapSize < 2) fail("cascades.mapSize must be >= 2, got " + str(p.mapSize));
    if (p.padTexels < 0 || 2 * p.padTexels >= p.mapSize)
        fail("padding (" + str(p.padTexels) + " texels) must be >= 0 and under half of the cascade's map size (" +
             str(p.mapSize) + ")");
    const float d = p.zExtensionDistance;
    if (p.zExtension == ZExtension::Distance && !(d >= 0.0f && std::isfinite(d)))
        fail("cascades.zExtensionDistance must be >= 0, got " + str(d));
    if (!(p.lightDepth >= 0.0f && std::isfinite(p.lightDepth)))
        fail("cascades.lightDepth must be >= 0, got " + str(p.lightDepth));
}

// Box before snapping, with the size the texel grid is derived from: for the sphere the exact
// diameter (2r is exact in float; max - min of a translated box is not).
struct SliceBox {
    Aabb ls;
    glm::vec2 size{0.0f};
};

// Tight AABB of the slice corners in ls: the crop box (m_i, M_i) of seed 000, as in seed 002.
SliceBox cornerBox(Corners ls, const glm::mat4& lsView) {
    for (glm::vec3& p : ls) p = glm::vec3(lsView * glm::vec4(p, 1.0f));
    const Aabb box = boundsOf(ls);
    return {box, glm::vec2(box.extent())};
}

SliceBox cornerBox(const CameraParams& cam, float vsNear, float vsFar, const glm::mat4& lsView) {
    return cornerBox(sliceCornersFromCamera(cam, vsNear, vsFar), lsView);
}

struct Sphere {
    float vsDepth;  // centre on the view axis
    float radius;
};

// Smallest sphere around the slice [n, f] (seed 001 uses a sphere; this centre is tighter than
// the corners' centroid). By symmetry the centre is on the view axis at depth z; with
// k^2 = tan^2(fovX/2) + tan^2(fovY/2), near and far corners are equidistant when
// (z-n)^2 + n^2 k^2 = (f-z)^2 + f^2 k^2, i.e. z = (n+f)(1+k^2)/2; past f, the far face's circle
// already holds the near corners, so z = f. Depends only on fov, aspect, n, f: the radius is
// bit-identical whatever the camera's position or orientation.
Sphere sliceSphere(const CameraParams& cam, double n, double f) {
    const double ty = std::tan(0.5 * static_cast<double>(cam.fovY));
    const double tx = ty * cam.aspect;
    const double k2 = tx * tx + ty * ty;
    const double z = std::min(f, 0.5 * (n + f) * (1.0 + k2));
    const double r2 = std::max((z - n) * (z - n) + n * n * k2, (f - z) * (f - z) + f * f * k2);
    // Up to 1/16 m (seed 001), after a 1e-5 relative pad so float-computed corners stay inside
    // even when the exact radius is already a multiple of 1/16.
    const double radius = std::ceil(std::sqrt(r2) * (1.0 + 1e-5) * 16.0) / 16.0;
    return {static_cast<float>(z), static_cast<float>(radius)};
}

SliceBox sphereBox(const CameraParams& cam, float vsNear, float vsFar, const glm::mat4& lsView) {
    const Sphere s = sliceSphere(cam, vsNear, vsFar);
    const glm::vec4 wsCentre = inverseViewMatrix(cam) * glm::vec4(0.0f, 0.0f, -s.vsDepth, 1.0f);
    const glm::vec3 lsCentre(lsView * wsCentre);
    return {{lsCentre - s.radius, lsCentre + s.radius}, glm::vec2(2.0f * s.radius)};
}

// The sphere around the slice corners' mean, through its farthest corner, its radius rounded up to
// 1/16 m: Babylon.js stabilizeCascades (cascadedShadowGenerator.pure.js:473-483, `Math.ceil(r * 16) / 16`),
// looser than sphereBox's smallest one and off the view axis for a slice seen at an angle.
SliceBox meanSphereBox(const Corners& ws, const glm::mat4& lsView) {
    glm::dvec3 centre(0.0);
    for (const glm::vec3& c : ws) centre += glm::dvec3(c);
    centre /= 8.0;
    double r = 0.0;
    for (const glm::vec3& c : ws) r = std::max(r, glm::distance(glm::dvec3(c), centre));
    const float radius = float(std::ceil(r * 16.0) / 16.0);
    const glm::vec3 lsCentre(lsView * glm::vec4(glm::vec3(centre), 1.0f));
    return {{lsCentre - radius, lsCentre + radius}, glm::vec2(2.0f * radius)};
}

// three.js r187 (examples/jsm/csm/CSM.js, _updateShadowBounds): a square as wide as the slice's
// longer diagonal, the far face's or the body's (far corner (+x,+y) to near corner (-x,-y)), so
// its size does not depend on the view's orientation; centred on the slice's light-space box.
SliceBox diagonalBox(const CameraParams& cam, float vsNear, float vsFar, const glm::mat4& lsView) {
    const Corners ws = sliceCornersFromCamera(cam, vsNear, vsFar);  // near (-,-) (+,-) (+,+) (-,+), then far
    const float width = std::max(glm::distance(ws[6], ws[4]), glm::distance(ws[6], ws[0]));
    SliceBox box = cornerBox(cam, vsNear, vsFar, lsView);
    const glm::vec2 centre(box.ls.center());
    box.ls.min.x = centre.x - 0.5f * width, box.ls.max.x = centre.x + 0.5f * width;
    box.ls.min.y = centre.y - 0.5f * width, box.ls.max.y = centre.y + 0.5f * width;
    box.size = glm::vec2(width);
    return box;
}

// The box's centre onto whole texels of size / m, the box kept at its size around it; with an even
// m its edges land on the same grid. Floored: three.js (CSM.js update()); rounded: Babylon.js,
// whose origin shift (_computeMatrices) moves the centre to the nearest multiple of the texel.
Aabb snapCentreToTexels(Aabb box, glm::vec2 size, int mapSize, const std::optional<glm::dvec2>& phase, bool round) {
    for (int axis = 0; axis < 2; ++axis) {
        const double texel = double(size[axis]) / double(mapSize);
        if (!(texel > 0.0)) continue;
        const double shift = phase ? (*phase)[axis] : 0.0;
        const double centre = 0.5 * (double(box.min[axis]) + double(box.max[axis])) + shift;
        const double snapped = (round ? std::round(centre / texel) : std::floor(centre / texel)) * texel - shift;
        box.min[axis] = static_cast<float>(snapped - 0.5 * double(size[axis]));
        box.max[axis] = static_cast<float>(snapped + 0.5 * double(size[axis]));
    }
    return box;
}

// SDSM (Lauritzen et al. 2011, section 3.2): the light box of the samples the cascade holds,
// not of its whole slice. x,y padded by whole texels for the filter's taps and the normal
// offset (samplePadTexels, or the filter's padding when that is wider); z widened by 1% of its
// range so the farthest receiver is not on the far plane.
SliceBox samplesBox(const Aabb& lsSamples, const SliceBox& slice, const FitParams& p) {
    Aabb b = lsSamples;
    const glm::vec2 size0 = glm::max(glm::vec2(b.extent()), glm::vec2(1e-3f));
    const float m = static_cast<float>(p.mapSize);
    // Padding k texels of the padded box on each side: size = size0 m / (m - 2k).
    const float pad = std::max(p.samplePadTexels, static_cast<float>(p.padTexels));
    glm::vec2 size = size0 * (m / std::max(1.0f, m - 2.0f * pad));
    if (p.stabilize) {
        // Steps of 1/16 of the slice's box: the size (so the texel) is the same over frames
        // whose samples differ a little, and snapping then keeps the grid still.
        const glm::vec2 step = glm::max(slice.size / 16.0f, glm::vec2(1e-3f));
        size = glm::ceil(size / step) * step;
    }
    const glm::vec2 centre(b.center());
    b.min.x = centre.x - 0.5f * size.x, b.max.x = centre.x + 0.5f * size.x;
    b.min.y = centre.y - 0.5f * size.y, b.max.y = centre.y + 0.5f * size.y;
    const float zPad = 0.01f * std::max(b.extent().z, 1e-2f);
    b.min.z -= zPad, b.max.z += zPad;
    return {b, size};
}

// Seed 004 PCF padding: the slice of width w keeps `pad` texels of the m-texel map on each side,
// so the grown width W satisfies W (m - 2 pad) / m = w.
SliceBox padBox(SliceBox box, int pad, int mapSize) {
    if (pad == 0) return box;
    for (int axis = 0; axis < 2; ++axis) {
        const float grow = box.size[axis] * float(pad) / float(mapSize - 2 * pad);
        box.ls.min[axis] -= grow;
        box.ls.max[axis] += grow;
        box.size[axis] += 2.0f * grow;
    }
    return box;
}

// Seed 001 texel snapping: min x,y moved down to whole texels, max = min + size, so the box only
// ever moves by whole texels and a static caster rasterises to the same texels every frame.
// Moving min down can uncover up to one texel at the max side, so the texel is size / (m - 1):
// the m-texel box then still covers the unsnapped one. In world light space the snap is float
// math on the box's own coordinates (large far from the origin, so the multiple is rounded to
// their float spacing). `phase` (camera-relative) is where this light space's origin lies in the
// world's, in double, so the grid is the world's multiples of the texel with the box near zero.
Aabb snapToTexels(Aabb box, glm::vec2 size, int mapSize, const std::optional<glm::dvec2>& phase) {
    for (int axis = 0; axis < 2; ++axis) {
        const float texel = size[axis] / static_cast<float>(mapSize - 1);
        if (!(texel > 0.0f)) continue;
        if (phase) {
            const double t = texel;
            const double world = (*phase)[axis] + static_cast<double>(box.min[axis]);
            box.min[axis] = static_cast<float>(std::floor(world / t) * t - (*phase)[axis]);
        } else {
            box.min[axis] = std::floor(box.min[axis] / texel) * texel;
        }
        box.max[axis] = box.min[axis] + texel * static_cast<float>(mapSize);
    }
    return box;
}

// The frame the box is fitted in: the camera in it, scene -> ls, and the grid's phase.
struct LightFrame {
    CameraParams camera;
    glm::mat4 lsView{1.0f};
    std::optional<glm::dvec2> phase;  // camera-relative: the eye's world ls x,y
};

LightFrame lightFrame(const CameraParams& cam, const glm::mat4& rotation, const FitParams& p) {
    LightFrame f{cam, rotation, std::nullopt};
    if (p.cameraRelative) {
        // ls = R (x - eye): every number the fit and the snap see is metres around the camera.
        f.camera.wsPosition = glm::vec3(0.0f);
        f.camera.wsTarget = cam.wsTarget - cam.wsPosition;
        f.lsView = rotation * glm::translate(glm::mat4(1.0f), -cam.wsPosition);
        const glm::dvec3 wsEye = glm::dvec3(p.wsOrigin) + glm::dvec3(cam.wsPosition);
        f.phase = glm::dvec2(glm::dmat3(glm::mat3(rotation)) * wsEye);
    } else if (p.wsOrigin != glm::vec3(0.0f)) {
        // World light space in float, as an engine without camera-relative math builds it.
        f.camera.wsPosition = cam.wsPosition + p.wsOrigin;
        f.camera.wsTarget = cam.wsTarget + p.wsOrigin;
        f.lsView = rotation * glm::translate(glm::mat4(1.0f), p.wsOrigin);
    }
    return f;
}

// How far toward the sun (+Z in ls) the box reaches beyond the slice (seed 000: casters outside
// the slice; seed 003: light depth range from the scene bounds; seed 001: pancaking).
Aabb extendZ(Aabb box, const glm::mat4& lsView, const FitParams& p) {
    if (p.zExtension == ZExtension::Distance) {
        box.max.z += p.zExtensionDistance;
    } else if (p.zExtension == ZExtension::SceneBounds) {
        // Union, not replace: the slice itself must stay inside even if the bounds miss it.
        const Aabb lsScene = transformAabb(lsView, p.wsSceneBounds);
        box.min.z = std::min(box.min.z, lsScene.min.z);
        box.max.z = std::max(box.max.z, lsScene.max.z);
    }
    // Babylon.js with depthClamp (cascadedShadowGenerator.pure.js _computeMatrices): the slice's depth
    // range cut to the casters' light-space bounds where they lie inside it, at least 1 m deep;
    // casters toward the sun are clamped onto the near plane as any pancake's.
    if (p.zExtension == ZExtension::Pancake && p.pancakeToCasters) {
        const Aabb casters = transformAabb(lsView, p.wsSceneBounds);
        if (casters.max.z >= box.min.z) {
            box.max.z = std::min(box.max.z, casters.max.z);
            box.min.z = std::min(box.max.z - 1.0f, std::max(box.min.z, casters.min.z));
        }
    }
    // three.js's light camera spans lightNear..lightFar from a point lightMargin beyond the slice
    // (CSM.js update()): a fixed depth that sets what a normalised-depth bias means in metres.
    if (p.lightDepth > 0.0f) box.min.z = box.max.z - p.lightDepth;
    return box;  // None, Pancake: the slice's range (Pancake clamps casters to the near plane)
}

}  // namespace

// The sun is at (cos el cos az, sin el, cos el sin az) from the scene; light travels opposite.
glm::vec3 lightDirection(float azimuthDeg, float elevationDeg) {
    if (!std::isfinite(azimuthDeg)) fail("light.azimuth must be finite, got " + str(azimuthDeg));
    if (!std::isfinite(elevationDeg))
        fail("light.elevation must be finite, got " + str(elevationDeg));
    const float az = glm::radians(azimuthDeg);
    const float el = glm::radians(elevationDeg);
    const glm::vec3 wsToSun(std::cos(el) * std::cos(az), std::sin(el), std::cos(el) * std::sin(az));
    return -glm::normalize(wsToSun);
}

glm::mat4 lightViewMatrix(glm::vec3 wsLightDir) {
    const float len2 = glm::dot(wsLightDir, wsLightDir);
    if (!(len2 > 0.0f) || !std::isfinite(len2))
        fail("wsLightDir must be finite and non-zero, got (" + str(wsLightDir.x) + ", " +
             str(wsLightDir.y) + ", " + str(wsLightDir.z) + ")");
    const glm::vec3 dir = wsLightDir / std::sqrt(len2);
    // Eye at the origin: rotation only, so the texel grid moves with nothing but the light.
    return glm::lookAt(glm::vec3(0.0f), dir, stableUp(dir));
}

CascadeFit fitCascade(const CameraParams& cam, std::span<const float> splits, int index,
                      glm::vec3 wsLightDir, const FitParams& p) {
    validateCamera(cam);
    validateSplits(splits, index);
    validateFit(p);
    CascadeFit out;
    const glm::mat4 rotation = lightViewMatrix(wsLightDir);
    LightFrame frame = lightFrame(cam, rotation, p);
    frame.camera.fovY = std::max(frame.camera.fovY, std::min(p.minFovY, glm::radians(179.0f)));
    out.lsView = frame.lsView;
    const auto i = static_cast<std::size_t>(index);
    out.vsNear = p.fit == FitMode::Scene ? splits[0] : splits[i];  // seed 004 "fit to scene"
    out.vsFar = splits[i + 1];
    const auto corners = [&] {
        if (!p.float32Corners) return sliceCornersFromCamera(frame.camera, out.vsNear, out.vsFar);
        const double range = p.float32Corners->farPlane - p.float32Corners->nearPlane;
        return sliceCornersThroughFloat32Inverse(*p.float32Corners, (out.vsNear - p.float32Corners->nearPlane) / range,
                                                 (out.vsFar - p.float32Corners->nearPlane) / range);
    };
    const bool meanSphere = p.fit == FitMode::Sphere && p.sphereAroundCornersMean;
    SliceBox box = meanSphere                   ? meanSphereBox(corners(), rotation)
                   : p.fit == FitMode::Sphere   ? sphereBox(frame.camera, out.vsNear, out.vsFar, rotation)
                   : p.fit == FitMode::Diagonal ? diagonalBox(frame.camera, out.vsNear, out.vsFar, rotation)
                                                : cornerBox(corners(), rotation);
    if (p.fit == FitMode::Samples && p.lsSamples) {
        // The reduction's bounds are in the rotation-only frame of scene coordinates: moved into
        // this one by lsView's translation.
        const glm::vec3 shift(frame.lsView[3]);
        box = samplesBox({p.lsSamples->min + shift, p.lsSamples->max + shift}, box, p);
        out.fittedToSamples = true;
    } else {
        box = padBox(box, p.padTexels, p.mapSize);
    }
    if (p.stabilize && p.snap != Snap::BoxFloor)
        box.ls = snapCentreToTexels(box.ls, box.size, p.mapSize, frame.phase, p.snap == Snap::CentreRound);
    else if (p.stabilize) box.ls = snapToTexels(box.ls, box.size, p.mapSize, frame.phase);
    out.lsSlice = box.ls;
    const Aabb ls = extendZ(box.ls, out.lsView, p);
    out.lsBox = ls;
    // ls looks down -Z: the near plane distance is -max.z, the far one -min.z.
    out.lsProj = glm::ortho(ls.min.x, ls.max.x, ls.min.y, ls.max.y, -ls.max.z, -ls.min.z);
    out.viewProj = out.lsProj * out.lsView;
    out.texelWorldSize = (ls.max.x - ls.min.x) / static_cast<float>(p.mapSize);
    out.mapSize = p.mapSize;
    return out;
}

}  // namespace st::csm
