#version 450 core
// Step 1 of seed 001's screen-space path: the preset's filter, cascade selection, bias and blend
// band per pixel (shadowFactor, as main.frag shades), drawn with main.vert and the main pass's
// coverage. x: the factor, 0 where the surface faces away from the sun (seed 001 shadows those
// pixels); y: the view depth of this camera, metres, for the depth-aware blur and upsample.
#include "interface.h"
#include "shadow_sampling.glsl"

layout(binding = ST_BINDING_BASE_COLOR) uniform sampler2D uBaseColorTex;
in vec3 vWsPosition;
in vec3 vWsNormal;
in vec2 vUv;
in float vVsDepth;
out vec2 oMask;

void main() {
    vec4 base = baseColor;
    if (hasTexture != 0) base *= texture(uBaseColorTex, vUv);
    if (alphaMask != 0 && base.a < alphaCutoff) discard;
    vec3 n = normalize(vWsNormal);
    if (!gl_FrontFacing) n = -n;
    float nDotL = dot(n, wsToSun.xyz);
    ShadowResult s = shadowFactor(vWsPosition, n, nDotL, vVsDepth);
    // 1 / gl_FragCoord.w is the clip w, the distance along the view axis for a perspective camera.
    oMask = vec2(nDotL > 0.0 ? s.factor : 0.0, 1.0 / gl_FragCoord.w);
}
