#version 450 core
// The measurement pass's first half (docs/architecture.md#how-the-product-is-measured): what each
// pixel's surface is, drawn with main.vert and the main pass's coverage rules (alpha test,
// culling), so every figure belongs to a pixel the shaded image shows. None of it depends on a
// shadow setting, so a view keeps it while candidates change (renderer/render/measure_pass.h);
// measure_shadow.frag then tests the shadows of these pixels. Targets (RGBA32F):
//   0: ws position, w = 1 (the clear value 0 marks pixels with no surface)
//   1: ws shading normal, facing the viewer as main.frag lights it; w = N.L
//   2: the triangle's own (geometric) normal, on the viewer's side like the shading normal;
//      w = its N.L. Smooth shading normals bend away from it, but rays and depth maps see it.
//   3: xyz the position's screen x derivative (what main.frag's dFdx gives), w the view depth
//      from the cascade camera (it drives interval selection)
//   4: xyz the position's screen y derivative
#include "interface.h"

layout(binding = ST_BINDING_BASE_COLOR) uniform sampler2D uBaseColorTex;
in vec3 vWsPosition;
in vec3 vWsNormal;
in vec2 vUv;
in float vVsDepth;
layout(location = 0) out vec4 oPosition;
layout(location = 1) out vec4 oNormal;
layout(location = 2) out vec4 oGeometry;
layout(location = 3) out vec4 oDx;
layout(location = 4) out vec4 oDy;

void main() {
    // Before the discard, so the whole 2x2 quad still runs when they are taken.
    vec3 wsDx = dFdx(vWsPosition);
    vec3 wsDy = dFdy(vWsPosition);
    vec4 base = baseColor;
    if (hasTexture != 0) base *= texture(uBaseColorTex, vUv);
    if (alphaMask != 0 && base.a < alphaCutoff) discard;
    vec3 n = normalize(vWsNormal);
    if (!gl_FrontFacing) n = -n;
    oPosition = vec4(vWsPosition, 1.0);
    oNormal = vec4(n, dot(n, wsToSun.xyz));
    vec3 g = normalize(cross(wsDx, wsDy));  // the position's derivatives span the triangle's plane
    if (dot(g, n) < 0.0) g = -g;
    oGeometry = vec4(g, dot(g, wsToSun.xyz));
    oDx = vec4(wsDx, vVsDepth);
    oDy = vec4(wsDy, 0.0);
}
