#version 450 core
#include "interface.h"
// Depth only; masked materials (foliage cards) are alpha-tested so their holes let light through.
layout(binding = ST_BINDING_BASE_COLOR) uniform sampler2D uBaseColorTex;
in vec2 vUv;
void main() {
    if (alphaMask != 0) {
        float a = baseColor.a * (hasTexture != 0 ? texture(uBaseColorTex, vUv).a : 1.0);
        if (a < alphaCutoff) discard;
    }
}
