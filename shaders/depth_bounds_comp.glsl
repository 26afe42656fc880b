#version 450 core
// Sample distribution shadow maps (Lauritzen, Salvi, Lefohn 2011), the reduction: the camera's
// depth buffer reduced to the nearest and farthest view depth seen (mode 0), or to the
// light-space bounds of the samples each cascade holds (mode 1, the cascade picked by view depth
// as interval selection does). Background (depth 1, the clear value) is no sample.
// Floats are reduced as order-preserving uint keys with atomicMin/Max, first per work group in
// shared memory, then once per group into the result buffer.
#include "interface.h"
layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = ST_BINDING_REDUCE_DEPTH) uniform sampler2D uDepth;

// renderer/render/depth_bounds_pass.cpp's ReduceResult, std430: tightly packed uints.
layout(std430, binding = ST_STORAGE_REDUCE) buffer ReduceResult {
    uint depthKeys[4];                      // min key, max key, samples, unused
    uint lsMinKeys[3 * ST_MAX_CASCADES];    // x, y, z of cascade i at 3i..3i+2
    uint lsMaxKeys[3 * ST_MAX_CASCADES];
    uint lsSamples[ST_MAX_CASCADES];
};

shared uint sDepth[3];
shared uint sMin[3 * ST_MAX_CASCADES];
shared uint sMax[3 * ST_MAX_CASCADES];
shared uint sCount[ST_MAX_CASCADES];

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

// Each invocation reduces a TILE x TILE block of texels in registers first: one set of shared
// atomics per block, not per texel (atomics are what llvmpipe pays for).
#define TILE 4

void main() {
    uint li = gl_LocalInvocationIndex;
    if (li < 3u * uint(ST_MAX_CASCADES)) {
        sMin[li] = 0xffffffffu;
        sMax[li] = 0u;
    }
    if (li < uint(ST_MAX_CASCADES)) sCount[li] = 0u;
    if (li == 0u) {
        sDepth[0] = 0xffffffffu;
        sDepth[1] = 0u;
        sDepth[2] = 0u;
    }
    barrier();
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
    ivec2 base = ivec2(gl_GlobalInvocationID.xy) * TILE;
    for (int y = 0; y < TILE; ++y) {
        for (int x = 0; x < TILE; ++x) {
            ivec2 p = base + ivec2(x, y);
            if (p.x >= reduceWidth || p.y >= reduceHeight) continue;
            float d = texelFetch(uDepth, p, 0).r;
            if (d >= 1.0) continue;
            // The pixel centre back through the camera: NDC, then view space (conventions.h).
            vec2 ndc = (vec2(p) + 0.5) / vec2(reduceWidth, reduceHeight) * 2.0 - 1.0;
            vec4 vs = reduceInvProj * vec4(ndc, d * 2.0 - 1.0, 1.0);
            vs /= vs.w;
            float vsDepth = -vs.z;
            if (reduceMode == 0) {
                dMin = min(dMin, vsDepth);
                dMax = max(dMax, vsDepth);
                ++seen;
            } else {
                int c = cascadeOf(vsDepth);
                if (c < 0) continue;
                vec3 ls = (reduceVsToLs * vec4(vs.xyz, 1.0)).xyz;
                lo[c] = min(lo[c], ls);
                hi[c] = max(hi[c], ls);
                ++held[c];
            }
        }
    }
    if (reduceMode == 0) {
        if (seen > 0u) {
            atomicMin(sDepth[0], orderedKey(dMin));
            atomicMax(sDepth[1], orderedKey(dMax));
            atomicAdd(sDepth[2], seen);
        }
    } else {
        for (int c = 0; c < reduceCascades; ++c) {
            if (held[c] == 0u) continue;
            for (int k = 0; k < 3; ++k) {
                atomicMin(sMin[3 * c + k], orderedKey(lo[c][k]));
                atomicMax(sMax[3 * c + k], orderedKey(hi[c][k]));
            }
            atomicAdd(sCount[c], held[c]);
        }
    }
    barrier();
    if (reduceMode == 0) {
        if (li == 0u && sDepth[2] > 0u) {
            atomicMin(depthKeys[0], sDepth[0]);
            atomicMax(depthKeys[1], sDepth[1]);
            atomicAdd(depthKeys[2], sDepth[2]);
        }
    } else if (li < 3u * uint(reduceCascades) && sCount[li / 3u] > 0u) {
        atomicMin(lsMinKeys[li], sMin[li]);
        atomicMax(lsMaxKeys[li], sMax[li]);
        if (li % 3u == 0u) atomicAdd(lsSamples[li / 3u], sCount[li / 3u]);
    }
}
