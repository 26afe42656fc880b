#version 450 core
#include "interface.h"
#include "moments.glsl"
// One moment-map layer made visible like a depth layer (depth_view.frag). Reads the cascade block
// (filter kind, 16-bit flag, EVSM exponent). OverlayBlock::brightness picks the image: 0 shows
// the first moment as depth (EVSM's warp undone, MSM's quantisation undone) on the same grey ramp;
// 1 shows the variance as the standard deviation in depth units, relative to the scene's depth
// span in the box, black (0) .. yellow (>= 1/16 of the span).
layout(binding = ST_BINDING_DEPTH_VIEW) uniform sampler2DArray uMomentsView;
in vec2 vUv;
out vec4 oColor;
void main() {
    vec4 m = texture(uMomentsView, vec3(vUv, float(layer)));
    float mean, variance;
    if (filterKind == ST_FILTER_MSM) {
        vec4 b = moments16 != 0 ? msmDequantise(m) : m;
        mean = b.x;
        variance = b.y - b.x * b.x;
    } else if (filterKind == ST_FILTER_VSM) {
        mean = m.x;
        variance = m.y - m.x * m.x;
    } else {
        // exp(c (2z - 1)) = w  =>  z = (log(w) / c + 1) / 2; the variance through the warp's slope.
        float c = evsmPosExp;
        mean = 0.5 * (log(max(m.x, 1e-30)) / c + 1.0);
        float slope = 2.0 * c * m.x;
        variance = (m.y - m.x * m.x) / max(slope * slope, 1e-30);
    }
    float span = max(depthHi - depthLo, 1e-6);
    if (brightness > 0.5) {
        float v = clamp(16.0 * sqrt(max(variance, 0.0)) / span, 0.0, 1.0);
        oColor = vec4(v, v, 0.25 * v, 1.0);
        return;
    }
    if (mean >= 0.9999) {
        oColor = vec4(0.05, 0.07, 0.2, 1.0);
        return;
    }
    float v = 1.0 - clamp((mean - depthLo) / span, 0.0, 1.0);
    oColor = vec4(vec3(0.15 + 0.85 * v), 1.0);
}
