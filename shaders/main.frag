#version 450 core
#include "interface.h"
#include "shadow_sampling.glsl"
#include "screen_shadow.glsl"

layout(binding = ST_BINDING_BASE_COLOR) uniform sampler2D uBaseColorTex;
in vec3 vWsPosition;
in vec3 vWsNormal;
in vec2 vUv;
in float vVsDepth;
out vec4 oColor;

// Screen pixels covered by one shadow texel, by the formula the metrics report
// (shadow_sampling.glsl). Heat map on log2: blue (1/16) .. green (1) .. red (16).
vec3 texelDensityColor(vec3 wsPos, int ci) {
    float pixelsPerTexel = screenPixelsPerTexel(texelJacobian(max(ci, 0), dFdx(wsPos), dFdy(wsPos)));
    if (ci < 0) return vec3(0.5);
    float v = clamp(log2(pixelsPerTexel) / 4.0, -1.0, 1.0);
    return v < 0.0 ? mix(vec3(0.0, 0.8, 0.1), vec3(0.1, 0.2, 1.0), -v) : mix(vec3(0.0, 0.8, 0.1), vec3(1.0, 0.1, 0.0), v);
}

// Seed 003's block pattern: each cascade's map filled with a checker of texelBlock texels in
// its tint, so a block's size on the scene shows what a texel of that cascade covers.
vec3 texelGridColor(vec3 wsPos, int ci) {
    if (ci < 0) return vec3(0.5);
    vec2 texel = (cascade[ci].shadowMatrix * vec4(wsPos, 1.0)).xy / cascade[ci].uvPerTexel.xy;
    ivec2 block = ivec2(floor(texel / float(max(texelBlock, 1))));
    return cascade[ci].tint.rgb * (((block.x + block.y) & 1) == 0 ? 1.0 : 0.45);
}

vec3 encodeSrgb(vec3 c) { return pow(clamp(c, 0.0, 1.0), vec3(1.0 / 2.2)); }

void main() {
    vec4 base = baseColor;
    if (hasTexture != 0) base *= texture(uBaseColorTex, vUv);
    if (alphaMask != 0 && base.a < alphaCutoff) discard;
    vec3 n = normalize(vWsNormal);
    if (!gl_FrontFacing) n = -n;  // double-sided surfaces are lit from the side we see
    float nDotL = dot(n, wsToSun.xyz);
    ShadowResult s = screenShadow != 0 ? screenShadowFactor(vWsPosition, n, vVsDepth)
                                       : shadowFactor(vWsPosition, n, nDotL, vVsDepth);
    vec3 density = texelDensityColor(vWsPosition, s.cascade);  // derivatives: uniform flow
    float direct = intensity * max(nDotL, 0.0) * s.factor;
    vec3 color = base.rgb * (ambient + direct);
    if (viewMode == ST_VIEW_CASCADES && s.cascade >= 0)
        color = cascade[s.cascade].tint.rgb * (0.25 + 0.75 * (ambient + direct));
    else if (viewMode == ST_VIEW_TEXEL_DENSITY)
        color = density * (0.5 + 0.5 * max(nDotL, 0.0));
    else if (viewMode == ST_VIEW_TEXEL_GRID)
        color = texelGridColor(vWsPosition, s.cascade) * (0.4 + 0.6 * (ambient + direct));
    else if (viewMode == ST_VIEW_SHADOW)
        color = vec3(nDotL > 0.0 ? s.factor : 0.0);
    oColor = vec4(encodeSrgb(color), 1.0);
}
