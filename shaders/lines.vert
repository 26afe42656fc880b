#version 450 core
#include "interface.h"
layout(location = ST_ATTRIB_POSITION) in vec3 aPosition;  // ws
layout(location = ST_ATTRIB_COLOR) in vec3 aColor;
out vec3 vColor;
void main() {
    vColor = aColor;
    gl_Position = viewProj * vec4(aPosition, 1.0);
}
