#version 450 core
#include "interface.h"
#include "subpixel_snap.glsl"
// Invariant: the depth prepass (shadow_depth.vert) and the main pass (main.vert) must give the
// same depth, since the main pass tests GL_LEQUAL against the prepass and writes none.
invariant gl_Position;
layout(location = ST_ATTRIB_POSITION) in vec3 aPosition;  // ws
layout(location = ST_ATTRIB_NORMAL) in vec3 aNormal;      // ws
layout(location = ST_ATTRIB_UV) in vec2 aUv;
out vec3 vWsPosition;
out vec3 vWsNormal;
out vec2 vUv;
out float vVsDepth;  // positive distance along the cascade camera's view axis, compared with the splits
void main() {
    vWsPosition = aPosition;
    vWsNormal = aNormal;
    vUv = aUv;
    vVsDepth = -(view * vec4(aPosition, 1.0)).z;
    gl_Position = snapToSubpixels(viewProj * vec4(aPosition, 1.0));
}
