#version 450 core
#include "limits.h"
#include "shadow_sampling.glsl"

layout(binding = ST_BINDING_BASE_COLOR) uniform sampler2D uBaseColorTex;
uniform vec4 uBaseColor;
uniform bool uHasTexture;
uniform bool uAlphaMask;
uniform float uAlphaCutoff;
uniform vec3 uWsToSun;  // unit vector toward the sun
uniform float uIntensity;
uniform float uAmbient;
uniform int uViewMode;

in vec3 vWsPosition;
in vec3 vWsNormal;
in vec2 vUv;
in float vVsDepth;
out vec4 oColor;

// Seed 002's red/green/blue first, then distinct hues for cascades 4..8.
const vec3 kTints[ST_MAX_CASCADES] = vec3[](
    vec3(1.0, 0.25, 0.25), vec3(0.25, 1.0, 0.25), vec3(0.3, 0.45, 1.0), vec3(1.0, 1.0, 0.2),
    vec3(1.0, 0.3, 1.0), vec3(0.2, 1.0, 1.0), vec3(1.0, 0.6, 0.1), vec3(0.6, 0.3, 1.0));

// Screen pixels covered by one shadow texel, by the formula the metrics report
// (shadow_sampling.glsl). Heat map on log2: blue (1/16) .. green (1) .. red (16).
vec3 texelDensityColor(vec3 wsPos, int cascade) {
    float pixelsPerTexel = screenPixelsPerTexel(texelJacobian(max(cascade, 0), dFdx(wsPos), dFdy(wsPos)));
    if (cascade < 0) return vec3(0.5);
    float v = clamp(log2(pixelsPerTexel) / 4.0, -1.0, 1.0);
    return v < 0.0 ? mix(vec3(0.0, 0.8, 0.1), vec3(0.1, 0.2, 1.0), -v) : mix(vec3(0.0, 0.8, 0.1), vec3(1.0, 0.1, 0.0), v);
}

vec3 encodeSrgb(vec3 c) { return pow(clamp(c, 0.0, 1.0), vec3(1.0 / 2.2)); }

void main() {
    vec4 base = uBaseColor;
    if (uHasTexture) base *= texture(uBaseColorTex, vUv);
    if (uAlphaMask && base.a < uAlphaCutoff) discard;
    vec3 n = normalize(vWsNormal);
    if (!gl_FrontFacing) n = -n;  // double-sided surfaces are lit from the side we see
    float nDotL = dot(n, uWsToSun);
    ShadowResult s = shadowFactor(vWsPosition, n, nDotL, vVsDepth);
    vec3 density = texelDensityColor(vWsPosition, s.cascade);  // derivatives: uniform flow
    float direct = uIntensity * max(nDotL, 0.0) * s.factor;
    vec3 color = base.rgb * (uAmbient + direct);
    if (uViewMode == ST_VIEW_CASCADES && s.cascade >= 0)
        color = kTints[s.cascade] * (0.25 + 0.75 * (uAmbient + direct));
    else if (uViewMode == ST_VIEW_TEXEL_DENSITY)
        color = density * (0.5 + 0.5 * max(nDotL, 0.0));
    else if (uViewMode == ST_VIEW_SHADOW)
        color = vec3(nDotL > 0.0 ? s.factor : 0.0);
    oColor = vec4(encodeSrgb(color), 1.0);
}
