#version 450 core
#include "interface.h"
// One cascade's map (its tile of its texture, uvRect) made visible: the depth above the tile's mean
// plane (depthPlane, fitted to its written texels) remapped from [depthLo, depthHi] (the 1st..99th
// percentile of those) to a grey ramp, near = bright; texels never written (depth 1) in dark blue.
// depthHi < 0: the raw stored depth in red, for ShadowMapView to find that range.
layout(binding = ST_BINDING_DEPTH_VIEW) uniform sampler2DArray uDepth;
in vec2 vUv;
out vec4 oColor;
void main() {
    // The outline is 1.5 output pixels wide along the tile's own edge.
    vec2 edge = min(vUv, 1.0 - vUv) / fwidth(vUv);
    if (tileBorder != 0 && min(edge.x, edge.y) < 1.5) {
        oColor = vec4(1.0, 0.85, 0.2, 1.0);
        return;
    }
    float d = texture(uDepth, vec3(mix(uvRect.xy, uvRect.zw, vUv), float(layer))).r;
    if (depthHi < 0.0) {
        oColor = vec4(d, 0.0, 0.0, 1.0);
        return;
    }
    if (d >= 1.0) {
        oColor = vec4(0.05, 0.07, 0.2, 1.0);
        return;
    }
    float range = max(depthHi - depthLo, 1e-6);
    // Depth above the tile's mean plane (the ground's slope toward the light, removed), so what
    // stands on the ground reads against it instead of the whole tile being one gradient.
    float above = d - dot(depthPlane.xyz, vec3(vUv, 1.0));
    float v = 1.0 - clamp((above - depthLo) / range, 0.0, 1.0);
    oColor = vec4(vec3(0.15 + 0.85 * v), 1.0);
}
