#version 450 core
#include "limits.h"
// Depth only; masked materials (foliage cards) are alpha-tested so their holes let light through.
layout(binding = ST_BINDING_BASE_COLOR) uniform sampler2D uBaseColorTex;
uniform bool uAlphaMask;
uniform bool uHasTexture;
uniform float uAlphaCutoff;
uniform float uBaseAlpha;
in vec2 vUv;
void main() {
    if (uAlphaMask) {
        float a = uBaseAlpha * (uHasTexture ? texture(uBaseColorTex, vUv).a : 1.0);
        if (a < uAlphaCutoff) discard;
    }
}
