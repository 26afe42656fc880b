#version 450 core
// Contact shadows (filter.contact "march"; Godot PR #118045): from the surface under each pixel,
// a short march toward the sun through the camera's depth. A sample that lies behind the visible
// surface at its own pixel, by more than a small tolerance and less than the thickness, is inside
// a caster. The result is min(map factor, contact factor): contact shadows only darken, and only
// near receivers, where a bias or a coarse map lost the shadow (peter-panning).
#include "interface.h"
layout(binding = ST_BINDING_SCREEN_SOURCE) uniform sampler2D uMapFactor;  // .r: the map's factor
layout(binding = ST_BINDING_SCREEN_FULL) uniform sampler2D uMask;         // .y: view depth, 0 = none
layout(binding = ST_BINDING_SCREEN_DEPTH) uniform sampler2D uDepth;       // window depth 0..1
out float oFactor;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float factor = texelFetch(uMapFactor, p, 0).r;
    float vs = texelFetch(uMask, p, 0).y;
    if (vs <= 0.0 || factor <= 0.0) {
        oFactor = factor;
        return;
    }
    vec2 size = vec2(textureSize(uMask, 0));
    vec3 ndc = vec3((vec2(p) + 0.5) / size, texelFetch(uDepth, p, 0).r) * 2.0 - 1.0;
    vec4 h = contactClipToWs * vec4(ndc, 1.0);
    vec3 ws = h.xyz / h.w;
    float step = contactLength / float(contactSteps);
    for (int i = 1; i <= contactSteps; ++i) {
        vec4 c = contactViewProj * vec4(ws + contactToSun.xyz * (step * float(i)), 1.0);
        if (c.w <= 0.0) break;
        vec2 uv = c.xy / c.w * 0.5 + 0.5;
        if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) break;
        float scene = texelFetch(uMask, ivec2(uv * size), 0).y;
        // clip w is the sample's view depth, as the mask's .y is the surface's (1 / gl_FragCoord.w).
        // The tolerance keeps the receiver's own surface, seen at a slant, from shadowing itself.
        float gap = c.w - scene;
        if (scene > 0.0 && gap > max(0.005, 0.002 * c.w) && gap < contactThickness) {
            factor = 0.0;
            break;
        }
    }
    oFactor = factor;
}
