#version 450 core
#include "interface.h"
// Shadow-map texels back-projected into the world (renderer/render/texel_cloud.h). A texel's
// point lies on the surface it was drawn from, so it is pulled a little toward the viewer to win
// the depth test against that surface instead of flickering with it.
layout(location = ST_ATTRIB_POSITION) in vec3 aPosition;  // ws
layout(location = ST_ATTRIB_COLOR) in vec3 aColor;
out vec3 vColor;
void main() {
    vColor = aColor;
    gl_Position = viewProj * vec4(aPosition, 1.0);
    gl_Position.z -= 2e-4 * gl_Position.w;
}
