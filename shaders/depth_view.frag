#version 450 core
#include "interface.h"
// One cascade's map (its tile of its texture, uvRect) made visible: depth remapped from
// [depthLo, depthHi] (the range the tile's own written texels span) to a grey ramp, near =
// bright; texels never written (depth 1) in dark blue. depthHi < 0: the raw stored depth in red,
// for ShadowMapView to find that range.
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
    float v = 1.0 - clamp((d - depthLo) / max(depthHi - depthLo, 1e-6), 0.0, 1.0);
    oColor = vec4(vec3(0.15 + 0.85 * v), 1.0);
}
