#version 450 core
// Step 2: the full-size mask to 1/N size. The depth kept is the block's nearest surface; the
// factor is the mean over the block's surface texels, each weighted by its depth against that
// nearest one, so a block straddling a silhouette holds the foreground's factor, not a mix.
// N = 1 copies the mask exactly (one texel of weight 1).
#include "interface.h"
#include "screen_blur.glsl"
layout(binding = ST_BINDING_SCREEN_SOURCE) uniform sampler2D uSource;
out vec2 oMask;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy) * screenDownsample;
    ivec2 last = textureSize(uSource, 0) - 1;
    float zNear = 0.0;
    for (int y = 0; y < screenDownsample; ++y)
        for (int x = 0; x < screenDownsample; ++x) {
            float z = texelFetch(uSource, min(p + ivec2(x, y), last), 0).y;
            if (z > 0.0 && (zNear == 0.0 || z < zNear)) zNear = z;
        }
    if (zNear == 0.0) {
        oMask = vec2(1.0, 0.0);  // no surface: nothing to shadow
        return;
    }
    float sum = 0.0, weights = 0.0;
    for (int y = 0; y < screenDownsample; ++y)
        for (int x = 0; x < screenDownsample; ++x) {
            vec2 t = texelFetch(uSource, min(p + ivec2(x, y), last), 0).xy;
            if (t.y <= 0.0) continue;
            float w = screenDepthWeight(t.y, zNear);
            sum += w * t.x;
            weights += w;
        }
    oMask = vec2(sum / weights, zNear);
}
