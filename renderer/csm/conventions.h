#pragma once
// Coordinate conventions shared by the math, the renderer and the shaders. One place, so a
// derivation reads the same everywhere.
//
// - World (ws): right-handed, metres, +Y up (glTF's convention).
// - View (vs): OpenGL camera space, looking down -Z. "View depth" is the positive distance
//   along the view axis, d = -vs.z; split distances are view depths.
// - Clip/NDC (cs): OpenGL, x,y,z in [-1, 1] (glm's default RH_NO), no clip-control change.
// - Light view (ls): rotation only (no translation), looking down -Z along the direction the
//   light travels; +Z points toward the sun. The rotation depends on the light direction alone
//   so a box snapped to the texel grid in ls stays on it when the camera moves.
// - Shadow texture (ts): x,y in [0, 1] with (0,0) at the first texel of the layer, z in [0, 1]
//   with 0 nearest the sun (GL depth after the default viewport transform).
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace st::csm {

// Bias matrix from light clip space (NDC) to shadow texture space: ts = 0.5 * cs + 0.5.
inline glm::mat4 clipToTexture() {
    glm::mat4 m(0.5f);
    m[3] = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    return m;
}

}  // namespace st::csm
