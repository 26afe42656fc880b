#version 450 core
in vec3 vColor;
uniform float uBrightness;
out vec4 oColor;
void main() { oColor = vec4(pow(vColor * uBrightness, vec3(1.0 / 2.2)), 1.0); }
