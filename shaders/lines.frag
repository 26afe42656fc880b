#version 450 core
#include "interface.h"
in vec3 vColor;
out vec4 oColor;
void main() { oColor = vec4(pow(vColor * brightness, vec3(1.0 / 2.2)), 1.0); }
