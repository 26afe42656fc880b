#version 450 core
#include "interface.h"
// The main pass's coverage without its shading (RenderOptions::shadeMain off): the same vertex
// shader, state and alpha test as main.frag, so the same fragments run and the counted work is
// the same, at a fraction of the time, when only the measurement pass's figures are needed.
layout(binding = ST_BINDING_BASE_COLOR) uniform sampler2D uBaseColorTex;
in vec2 vUv;
out vec4 oColor;
void main() {
    vec4 base = baseColor;
    if (hasTexture != 0) base *= texture(uBaseColorTex, vUv);
    if (alphaMask != 0 && base.a < alphaCutoff) discard;
    oColor = vec4(base.rgb, 1.0);
}
