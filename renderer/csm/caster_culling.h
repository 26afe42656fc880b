#pragma once
// Which clusters a cascade's map needs (issue 11 item 2), and the main pass's frustum test.
// Two tests, both conservative:
// - the light box, extended toward the light as far as the z-extension allows (culling.h);
// - with cascades.casterCulling, the volume the receivers of the cascade sweep toward the sun
//   (Bittner et al. 2011, "Shadow caster culling for efficient shadow mapping", sec. 4: a caster
//   matters only if it lies between the light and some receiver the camera sees). The receivers
//   are approximated by the cascade's slice of the view frustum; a caster whose light-space
//   bounds miss the slice's footprint on the map (the convex hull of its corners, padded by the
//   filter's reach and the normal offset), or lie wholly behind the slice, cannot darken a pixel
//   that reads this map.
// No GL.
#include "renderer/csm/frustum.h"
#include "renderer/csm/geometry.h"
#include "renderer/csm/light_fit.h"
#include "renderer/settings/settings.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <span>
#include <vector>

namespace st::csm {

struct CasterVolume {
    glm::mat4 lsView{1.0f};
    Aabb lsBox;             // the cascade's light box (already extended toward the light)
    bool pancake = false;   // casters in front of the box are clamped onto it: keep them
    bool sweep = false;     // the receiver test below applies
    std::vector<glm::vec2> lsHull;  // receivers' footprint in ls x,y, counter-clockwise
    float margin = 0.0f;    // metres the footprint is grown by (filter taps, normal offset)
    float lsReceiverMinZ = 0.0f;    // farthest receiver from the sun (ls z)
};

// The view depths whose pixels may read cascade `index`'s map: its slice; with map-based
// selection every depth (a pixel takes the first map whose box holds it); with a blend band
// (interval selection) also the previous slice, whose far end blends into this map.
std::array<float, 2> receiverDepthRange(const Settings& s, std::span<const float> splits, int index,
                                        const CascadeFit& fit);

// The volume of cascade `index` of a plan with these splits and fits.
CasterVolume casterVolume(const Settings& s, const CameraParams& cam, std::span<const float> splits,
                          int index, const CascadeFit& fit);

// Whether a caster with these world bounds may change what a pixel reads from the cascade.
bool casterMayShadow(const Aabb& wsBounds, const CasterVolume& v);

// The light-box test alone on light-space bounds (culling.h's rule): the lower bound counts the
// triangles whose own bounds pass it.
bool lsBoundsMeetBox(const Aabb& lsBounds, const Aabb& lsBox, bool pancake);

// Counter-clockwise convex hull (Andrew's monotone chain); collinear points dropped.
std::vector<glm::vec2> convexHull(std::vector<glm::vec2> points);

// The six planes of a clip-space frustum from its world -> clip matrix (Gribb and Hartmann,
// "Fast extraction of viewing frustum planes from the world-view-projection matrix", 2001):
// inside is dot(plane.xyz, p) + plane.w >= 0.
std::array<glm::vec4, 6> frustumPlanes(const glm::mat4& viewProj);
// False only if the box lies wholly outside one plane (conservative near the frustum's corners).
bool aabbInFrustum(const Aabb& wsBox, const std::array<glm::vec4, 6>& planes);

}  // namespace st::csm
