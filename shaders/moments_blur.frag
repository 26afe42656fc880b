#version 450 core
// Second half of the separable blur: the scratch texture blurred along y into one layer of the
// moment array, quantised for 16-bit MSM storage (Peters & Klein 2015, section 4).
#include "interface.h"
#include "moments.glsl"
#include "moments_blur.glsl"
layout(binding = ST_BINDING_MOMENT_SCRATCH) uniform sampler2D uScratch;
out vec4 oMoments;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int last = textureSize(uScratch, 0).y - 1;
    vec4 sum = vec4(0.0);
    for (int k = -blurRadius; k <= blurRadius; ++k)
        sum += blurWeight(k) * texelFetch(uScratch, ivec2(p.x, clamp(p.y + k, 0, last)), 0);
    oMoments = (filterKind == ST_FILTER_MSM && moments16 != 0) ? msmQuantise(sum) : sum;
}
