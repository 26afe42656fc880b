#version 450 core
// Sample distribution shadow maps (Lauritzen, Salvi, Lefohn 2011), the reduction: the camera's
// depth buffer reduced to the nearest and farthest depth seen (mode 0: GL depth, which view depth
// follows monotonically, so the caller converts the two ends), and in mode 1 also to the
// light-space bounds of the samples each cascade holds (the cascade picked by view depth as
// interval selection does). Background (depth 1, the clear value) is no sample.
// Floats are reduced as order-preserving uint keys with atomicMin/Max: each invocation reduces a
// block of texels in registers, then once into the result buffer. No shared memory and no
// barrier(): llvmpipe runs a shader with a barrier as one coroutine per invocation.
#include "interface.h"
layout(local_size_x = 8, local_size_y = 1) in;
layout(binding = ST_BINDING_REDUCE_DEPTH) uniform sampler2D uDepth;

// renderer/render/depth_bounds_pass.cpp's ReduceResult, std430: tightly packed uints.
layout(std430, binding = ST_STORAGE_REDUCE) buffer ReduceResult {
    uint depthKeys[4];                      // GL depth: min key, max key, samples; unused
    uint lsMinKeys[3 * ST_MAX_CASCADES];    // x, y, z of cascade i at 3i..3i+2
    uint lsMaxKeys[3 * ST_MAX_CASCADES];
    uint lsSamples[ST_MAX_CASCADES];
};

// Monotonic float -> uint: positive floats get the sign bit set, negative ones are inverted.
uint orderedKey(float f) {
    uint u = floatBitsToUint(f);
    return (u & 0x80000000u) != 0u ? ~u : (u | 0x80000000u);
}

float splitAt(int i) { return reduceSplits[i / 4][i % 4]; }

int cascadeOf(float vsDepth) {
    if (vsDepth < splitAt(0)) return -1;
    for (int i = 0; i < reduceCascades; ++i)
        if (vsDepth <= splitAt(i + 1)) return i;
    return -1;
}

// Each invocation reduces a TILE x TILE block of texels in registers: one set of atomics per
// block, not per texel (atomics are what llvmpipe pays for).
#define TILE 16

void main() {
    float dMin = 3.4e38, dMax = -3.4e38;
    uint seen = 0u;
    vec3 lo[ST_MAX_CASCADES];
    vec3 hi[ST_MAX_CASCADES];
    uint held[ST_MAX_CASCADES];
    for (int c = 0; c < ST_MAX_CASCADES; ++c) {
        lo[c] = vec3(3.4e38);
        hi[c] = vec3(-3.4e38);
        held[c] = 0u;
    }
    // The group's 8 invocations take neighbouring texels of a row, so their fetches are one
    // vector load: invocation i of a group reads columns i, i + 8, ... of the group's block.
    ivec2 base = ivec2(gl_WorkGroupID.xy) * ivec2(8 * TILE, TILE) + ivec2(gl_LocalInvocationID.x, 0);
    for (int y = 0; y < TILE; ++y) {
        for (int x = 0; x < TILE; ++x) {
            ivec2 p = base + ivec2(8 * x, y);
            if (p.x >= reduceWidth || p.y >= reduceHeight) continue;
            float d = texelFetch(uDepth, p, 0).r;
            if (d >= 1.0) continue;
            dMin = min(dMin, d);
            dMax = max(dMax, d);
            ++seen;
            if (reduceMode == 0) continue;
            // The pixel centre back through the camera: NDC, then view space (conventions.h).
            vec2 ndc = (vec2(p) + 0.5) / vec2(reduceWidth, reduceHeight) * 2.0 - 1.0;
            vec4 vs = reduceInvProj * vec4(ndc, d * 2.0 - 1.0, 1.0);
            vs /= vs.w;
            int c = cascadeOf(-vs.z);
            if (c < 0) continue;
            vec3 ls = (reduceVsToLs * vec4(vs.xyz, 1.0)).xyz;
            lo[c] = min(lo[c], ls);
            hi[c] = max(hi[c], ls);
            ++held[c];
        }
    }
    if (seen > 0u) {
        atomicMin(depthKeys[0], orderedKey(dMin));
        atomicMax(depthKeys[1], orderedKey(dMax));
        atomicAdd(depthKeys[2], seen);
    }
    if (reduceMode == 0) return;
    for (int c = 0; c < reduceCascades; ++c) {
        if (held[c] == 0u) continue;
        for (int k = 0; k < 3; ++k) {
            atomicMin(lsMinKeys[3 * c + k], orderedKey(lo[c][k]));
            atomicMax(lsMaxKeys[3 * c + k], orderedKey(hi[c][k]));
        }
        atomicAdd(lsSamples[c], held[c]);
    }
}
