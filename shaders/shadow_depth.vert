#version 450 core
#include "interface.h"
#include "subpixel_snap.glsl"
// Invariant: the depth prepass (shadow_depth.vert) and the main pass (main.vert) must give the
// same depth, since the main pass tests GL_LEQUAL against the prepass and writes none.
invariant gl_Position;
layout(location = ST_ATTRIB_POSITION) in vec3 aPosition;
layout(location = ST_ATTRIB_NORMAL) in vec3 aNormal;
layout(location = ST_ATTRIB_UV) in vec2 aUv;
out vec2 vUv;
void main() {
    vUv = aUv;
    vec3 p = aPosition;
    if (casterNormalOffset > 0.0) {
        // Babylon.js shadowMapVertexNormalBias.js: the caster moves into its surface by the offset
        // times sin of the angle between its normal and the sun (0 only in the shadow pass).
        vec3 n = normalize(aNormal);
        float nDotL = dot(n, wsToSun.xyz);
        p -= n * (casterNormalOffset * sqrt(max(1.0 - nDotL * nDotL, 0.0)));
    }
    gl_Position = snapToSubpixels(viewProj * vec4(p, 1.0));  // world -> light clip of the cascade being drawn
}
