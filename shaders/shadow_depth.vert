#version 450 core
#include "interface.h"
#include "subpixel_snap.glsl"
// Invariant: the depth prepass (shadow_depth.vert) and the main pass (main.vert) must give the
// same depth, since the main pass tests GL_LEQUAL against the prepass and writes none.
invariant gl_Position;
layout(location = ST_ATTRIB_POSITION) in vec3 aPosition;
layout(location = ST_ATTRIB_UV) in vec2 aUv;
out vec2 vUv;
void main() {
    vUv = aUv;
    gl_Position = snapToSubpixels(viewProj * vec4(aPosition, 1.0));  // world -> light clip of the cascade being drawn
}
