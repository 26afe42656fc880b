#pragma once
// Light view and the per-cascade orthographic fit (crop matrix).
#include "renderer/csm/float32_corners.h"
#include "renderer/csm/frustum.h"
#include "renderer/csm/geometry.h"
#include "renderer/settings/settings.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <span>

namespace st::csm {

// Direction the light travels (from the sun toward the scene), unit length, from the settings'
// azimuth (degrees from +X toward +Z) and elevation (degrees above the horizon).
glm::vec3 lightDirection(float azimuthDeg, float elevationDeg);

// Rotation-only light view (see conventions.h): ls -Z is wsLightDir. The up vector is chosen
// robustly (world +Y, or +Z when the light is within ~1 degree of vertical), so a sun straight
// up or down gives a finite orthonormal matrix.
glm::mat4 lightViewMatrix(glm::vec3 wsLightDir);

struct FitParams {
    FitMode fit = FitMode::Cascade;
    bool stabilize = false;           // snap the box's x,y origin to whole texels
    Snap snap = Snap::BoxFloor;       // how (CascadeSettings::snap)
    ZExtension zExtension = ZExtension::SceneBounds;
    float zExtensionDistance = 0.0f;  // metres toward the light, for ZExtension::Distance
    float lightDepth = 0.0f;          // metres from the box's near plane to its far one; 0 = the slice's far side
    bool pancakeToCasters = false;    // Pancake: depth tightened to wsSceneBounds (CascadeSettings::pancakeToCasters)
    int mapSize = 1024;               // texels per side of this cascade's map
    int padTexels = 0;                // texels added on each x,y side so kernels stay in the map
    Aabb wsSceneBounds;               // all casters; used by SceneBounds
    // FitMode::Samples: the light-space bounds of the visible samples the cascade holds
    // (depth_bounds.h); nullopt (no sample, or not reduced) falls back to the slice's box.
    std::optional<Aabb> lsSamples;
    float samplePadTexels = 2.0f;     // samples box grown by this many texels on each side (filter taps)
    // Fit for at least this vertical FOV (radians; 0 = the camera's): a zoom below it keeps the
    // box's size, so with stabilize its texel grid stays put (cascades.fitFovY).
    float minFovY = 0.0f;
    // Where the scene sits in the engine's world (Settings::origin). The box is fitted and snapped
    // in world coordinates (scene + wsOrigin), as an engine far from its origin would, and the
    // result expressed in scene coordinates (lsView maps scene -> ls).
    glm::vec3 wsOrigin{0.0f};
    // Light space centred on the camera's eye, the grid's phase (the eye's world light-space
    // position modulo a texel) taken in double: the snapping works in metres near the camera and
    // lands on the world grid however far the origin (cascades.cameraRelative).
    bool cameraRelative = false;
    // FitMode::Cascade: the slice's corners through the float32 inverse of this camera's matrices
    // (cascades.sliceCorners float32-inverse, Babylon.js) instead of from the camera's planes.
    std::optional<Float32Camera> float32Corners;
    bool sphereAroundCornersMean = false;  // FitMode::Sphere: cascades.sphereCentre corners-mean
};

struct CascadeFit {
    // Scene -> ls: lightViewMatrix(dir), times translate(wsOrigin) (world light space) or
    // translate(-eye) (camera-relative); rotation only when both are zero.
    glm::mat4 lsView{1.0f};
    glm::mat4 lsProj{1.0f};     // orthographic, ls box -> clip
    glm::mat4 viewProj{1.0f};   // lsProj * lsView: world -> light clip
    Aabb lsBox;                 // box in light view space; +Z toward the sun (max.z is the near side)
    Aabb lsSlice;               // lsBox before the z extension: the receivers' own range
    float texelWorldSize = 0.0f;// metres per texel along x (== y for sphere fit)
    int mapSize = 0;            // texels per side of this cascade's map (FitParams::mapSize)
    float vsNear = 0.0f;        // view depth range the cascade covers (scene fit: from camera near)
    float vsFar = 0.0f;
    bool fittedToSamples = false;  // FitMode::Samples with samples: the box is theirs, not the slice's
};

// Fits cascade `index` (slice [splits[index], splits[index+1]] of the camera, or
// [splits[0], splits[index+1]] for FitMode::Scene) in light space:
// - Cascade/Scene: tight AABB of the slice corners in ls (seed 000 crop matrix, seed 002).
// - Sphere: a square box around the slice's bounding sphere, radius rounded up to 1/16 m so its
//   size does not change when the camera rotates (seed 001).
// - Samples: the box of the visible samples (SDSM, Lauritzen et al. 2011, section 3.2), padded
//   by the wider of samplePadTexels and padTexels; with stabilize its size is rounded up to
//   1/16 of the slice box's so it changes in steps, then snapped like the others.
// - padTexels: the box grown on each x,y side so the slice keeps padTexels texels to the rim.
// - stabilize: min x,y moved down to a multiple of the texel size, max = min + size (seed 001).
//   Far from the origin in world light space (p.wsOrigin, float) the multiple is rounded to the
//   float grid of its large coordinates; with p.cameraRelative it is exact (see FitParams).
// - z: the slice's range, extended toward the sun by zExtensionDistance, or unioned with the
//   scene bounds (seed 003, using transformAabb), or left as is for None/Pancake.
CascadeFit fitCascade(const CameraParams& cam, std::span<const float> splits, int index,
                      glm::vec3 wsLightDir, const FitParams& p);

}  // namespace st::csm
