#version 450 core
// First half of the moment maps' separable Gaussian blur: the moments of each depth texel of
// layer `layer` (momentsOf), blurred along x into a float scratch texture. blurRadius 0 copies.
#include "interface.h"
#include "moments.glsl"
#include "moments_blur.glsl"
layout(binding = ST_BINDING_MOMENT_SOURCE) uniform sampler2DArray uDepthRaw;
out vec4 oMoments;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int last = textureSize(uDepthRaw, 0).x - 1;
    vec2 exponents = vec2(evsmPosExp, evsmNegExp);
    vec4 sum = vec4(0.0);
    for (int k = -blurRadius; k <= blurRadius; ++k) {
        float z = texelFetch(uDepthRaw, ivec3(clamp(p.x + k, 0, last), p.y, layer), 0).r;
        sum += blurWeight(k) * momentsOf(filterKind, z, exponents);
    }
    oMoments = sum;
}
