#version 450 core
// Step 5: the blurred mask back to full size, joint-bilateral: the four downsampled texels
// around the pixel, each weighted bilinearly and by its depth against the pixel's own (from the
// full-size mask), so a pixel takes its factor from texels on its own surface and a silhouette
// stays where it is. When no texel is on its surface (weights all but 0: a thin object) the
// texel of the nearest depth is taken. N = 1 reads the texel under the pixel exactly.
#include "interface.h"
#include "screen_blur.glsl"
layout(binding = ST_BINDING_SCREEN_SOURCE) uniform sampler2D uLow;
layout(binding = ST_BINDING_SCREEN_FULL) uniform sampler2D uFull;
out float oFactor;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float z = texelFetch(uFull, p, 0).y;
    if (z <= 0.0) {
        oFactor = 1.0;
        return;
    }
    vec2 at = (vec2(p) + 0.5) / float(screenDownsample) - 0.5;  // in downsampled texel centres
    ivec2 i0 = ivec2(floor(at));
    vec2 f = at - vec2(i0);
    ivec2 last = textureSize(uLow, 0) - 1;
    float sum = 0.0, weights = 0.0, nearest = 1.0, nearestGap = 1e30;
    for (int j = 0; j < 4; ++j) {
        ivec2 o = ivec2(j & 1, j >> 1);
        vec2 t = texelFetch(uLow, clamp(i0 + o, ivec2(0), last), 0).xy;
        if (t.y <= 0.0) continue;
        float bilinear = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
        float w = bilinear * screenDepthWeight(t.y, z);
        sum += w * t.x;
        weights += w;
        if (abs(t.y - z) < nearestGap) {
            nearestGap = abs(t.y - z);
            nearest = t.x;
        }
    }
    oFactor = weights > 1e-4 ? sum / weights : nearest;
}
