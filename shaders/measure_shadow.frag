#version 450 core
// The measurement pass's second half: the shadow test of every pixel measure_surface.frag drew,
// with the inputs main.frag's shading has there (position, normal, N.L, view depth and the
// position's screen derivatives, all stored as the float they were), so the factor is the one
// the image shows. Drawn over the whole target (fullscreen.vert). Output (RGBA32F):
//   x unfiltered test (one nearest compare in the selected cascade with the preset's bias,
//     receiver-plane bias included; no blend band), y filtered factor (the preset's filter and
//     blend band, as main.frag shades; with filter.screenSpace the upsampled mask main.frag
//     reads), z cascade (-1 beyond the shadow range), w screen pixels per texel;
//   all 0 where no surface was drawn.
#include "interface.h"
// Specialised (renderer/render/measure_pass.cpp, shadowDefines): the block members that choose a
// path through shadow_sampling.glsl are compile-time constants of this program, so the compiler
// drops the paths the preset does not take. llvmpipe runs every branch of a shader under a lane
// mask, taken or not: unspecialised, this pass cost 26 ms at 640x360 whatever it computed.
#ifdef ST_SPEC_FILTER_KIND
#define filterKind ST_SPEC_FILTER_KIND
#define storage ST_SPEC_STORAGE
#define selection ST_SPEC_SELECTION
#define receiverPlane ST_SPEC_RECEIVER_PLANE
#define screenShadow ST_SPEC_SCREEN_SHADOW
#endif
#ifdef ST_SPEC_NO_BLEND
#define blendBand 0.0
#endif
#ifdef ST_SPEC_NO_FADE
#define fadeBand 0.0
#endif
#include "shadow_sampling.glsl"
#include "screen_shadow.glsl"

layout(binding = ST_BINDING_SURFACE_POSITION) uniform sampler2D uPosition;
layout(binding = ST_BINDING_SURFACE_NORMAL) uniform sampler2D uNormal;
layout(binding = ST_BINDING_SURFACE_DX) uniform sampler2D uDx;
layout(binding = ST_BINDING_SURFACE_DY) uniform sampler2D uDy;
layout(location = 0) out vec4 oShadow;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 position = texelFetch(uPosition, p, 0);
    if (position.w == 0.0) {
        oShadow = vec4(0.0);
        return;
    }
    vec3 wsPos = position.xyz;
    vec4 normal = texelFetch(uNormal, p, 0);
    vec4 dx = texelFetch(uDx, p, 0);
    vec3 wsDx = dx.xyz;
    vec3 wsDy = texelFetch(uDy, p, 0).xyz;
    float vsDepth = dx.w;
    vec3 n = normal.xyz;
    float nDotL = normal.w;
    ShadowResult s = screenShadow != 0 ? screenShadowFactor(wsPos, n, vsDepth)
                                       : shadowFactorGrad(wsPos, n, nDotL, vsDepth, wsDx, wsDy);
    int ci = max(s.cascade, 0);
    vec2 dzduv = receiverPlane != 0 ? receiverPlaneSlope(ci, wsDx, wsDy) : vec2(0.0);
    float hard = hardShadow(ci, shadowCoord(ci, wsPos, n), tanToLight(nDotL), dzduv);
    mat2 j = texelJacobian(ci, wsDx, wsDy);
    bool inRange = s.cascade >= 0;
    oShadow = vec4(inRange ? hard : 1.0, s.factor, float(s.cascade), inRange ? screenPixelsPerTexel(j) : 0.0);
}
