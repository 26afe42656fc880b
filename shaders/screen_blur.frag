#version 450 core
// Steps 3 and 4 of seed 001 (horizontal, then vertical blur): one axis of the separable Gaussian
// on the downsampled mask, each tap's uploaded weight times its depth weight against the centre,
// renormalised over the taps on a surface (edge texels repeated at the image border).
#include "interface.h"
#include "screen_blur.glsl"
layout(binding = ST_BINDING_SCREEN_SOURCE) uniform sampler2D uSource;
out vec2 oMask;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 last = textureSize(uSource, 0) - 1;
    ivec2 axis = screenAxis == 0 ? ivec2(1, 0) : ivec2(0, 1);
    vec2 centre = texelFetch(uSource, p, 0).xy;
    if (centre.y <= 0.0) {
        oMask = centre;
        return;
    }
    float sum = 0.0, weights = 0.0;
    for (int k = -screenRadius; k <= screenRadius; ++k) {
        vec2 t = texelFetch(uSource, clamp(p + k * axis, ivec2(0), last), 0).xy;
        if (t.y <= 0.0) continue;
        float w = screenTapWeight(k) * screenDepthWeight(t.y, centre.y);
        sum += w * t.x;
        weights += w;
    }
    oMask = vec2(sum / weights, centre.y);
}
