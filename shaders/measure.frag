#version 450 core
// Per-pixel inputs of the metrics (docs/architecture.md#how-the-product-is-measured), as floats. Drawn
// with main.vert and the main pass's coverage rules (alpha test, culling), so every figure
// belongs to a pixel the shaded image shows. Targets:
//   0: ws position, w = 1 (the clear value 0 marks pixels with no surface)
//   1: ws shading normal, facing the viewer as main.frag lights it; w = N.L
//   2: x unfiltered test (one nearest compare in the selected cascade with the preset's bias,
//      receiver-plane bias included; no blend band), y filtered factor (the preset's filter and blend band, as main.frag
//      shades; with filter.screenSpace the upsampled mask main.frag reads), z cascade (-1
//      beyond the shadow range), w screen pixels per texel
//   3: the triangle's own (geometric) normal, on the viewer's side like the shading normal;
//      w = its N.L. Smooth shading normals bend away from it, but rays and depth maps see it.
#include "interface.h"
#include "shadow_sampling.glsl"
#include "screen_shadow.glsl"

layout(binding = ST_BINDING_BASE_COLOR) uniform sampler2D uBaseColorTex;
in vec3 vWsPosition;
in vec3 vWsNormal;
in vec2 vUv;
in float vVsDepth;  // from the cascade camera: it drives interval selection
layout(location = 0) out vec4 oPosition;
layout(location = 1) out vec4 oNormal;
layout(location = 2) out vec4 oShadow;
layout(location = 3) out vec4 oGeometry;

void main() {
    // Before the discard, so the whole 2x2 quad still runs when they are taken.
    vec3 wsDx = dFdx(vWsPosition);
    vec3 wsDy = dFdy(vWsPosition);
    vec4 base = baseColor;
    if (hasTexture != 0) base *= texture(uBaseColorTex, vUv);
    if (alphaMask != 0 && base.a < alphaCutoff) discard;
    vec3 n = normalize(vWsNormal);
    if (!gl_FrontFacing) n = -n;
    float nDotL = dot(n, wsToSun.xyz);
    ShadowResult s = screenShadow != 0 ? screenShadowFactor(vWsPosition, n, vVsDepth)
                                       : shadowFactor(vWsPosition, n, nDotL, vVsDepth);
    int ci = max(s.cascade, 0);
    vec2 dzduv = receiverPlane != 0 ? receiverPlaneSlope(ci, wsDx, wsDy) : vec2(0.0);
    float hard = hardShadow(ci, shadowCoord(ci, vWsPosition, n), tanToLight(nDotL), dzduv);
    mat2 j = texelJacobian(ci, wsDx, wsDy);
    bool inRange = s.cascade >= 0;
    oPosition = vec4(vWsPosition, 1.0);
    oNormal = vec4(n, nDotL);
    vec3 g = normalize(cross(wsDx, wsDy));  // the position's derivatives span the triangle's plane
    if (dot(g, n) < 0.0) g = -g;
    oGeometry = vec4(g, dot(g, wsToSun.xyz));
    oShadow = vec4(inRange ? hard : 1.0, s.factor, float(s.cascade), inRange ? screenPixelsPerTexel(j) : 0.0);
}
