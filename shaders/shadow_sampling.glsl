// Cascade selection, biasing and filtering of the shadow-map test, from CascadeBlock
// (shaders/interface.h). The CPU twin of the selection rules is renderer/csm/selection.cpp;
// tests/metrics/selection_match_gl_test.cpp checks both pick the same cascade on every pixel.
#include "interface.h"
// Storage "array" and "atlas": one depth array (the atlas is its only layer) on two samplers.
layout(binding = ST_BINDING_SHADOW_NEAREST) uniform sampler2DArrayShadow uShadowNearest;
layout(binding = ST_BINDING_SHADOW_LINEAR) uniform sampler2DArrayShadow uShadowLinear;
// Storage "textures": cascade i's own one-layer depth array on unit ST_BINDING_CASCADE_MAPS + i,
// linear compare only (one sampler per unit; the nearest test is a linear tap at a texel centre).
layout(binding = ST_BINDING_CASCADE_MAPS) uniform sampler2DArrayShadow uCascadeMaps[ST_MAX_CASCADES];

struct ShadowResult {
    float factor;  // 1 lit, 0 shadowed
    int cascade;   // -1 beyond the shadow range
};

vec3 shadowCoord(int i, vec3 wsPos, vec3 wsNormal) {
    vec3 p = wsPos + wsNormal * (normalOffset * cascade[i].texelWorld);
    return (cascade[i].shadowMatrix * vec4(p, 1.0)).xyz;
}

// d(shadow texel)/d(screen pixel) of cascade i: the shadow matrix is affine, so the texel
// derivatives are its linear part times the world-position derivatives. Taking those (not the
// derivatives of the texel coordinate itself) keeps pixels whose 2x2 quad straddles two cascades
// on their own cascade's figures.
// Texels are counted in the cascade's own texture (uvPerTexel), so an atlas tile or a smaller
// per-cascade map gives its own density.
mat2 texelJacobian(int i, vec3 wsDx, vec3 wsDy) {
    mat3 m = mat3(cascade[i].shadowMatrix);
    vec2 t = cascade[i].uvPerTexel.xy;
    return mat2((m * wsDx).xy / t, (m * wsDy).xy / t);
}

// Screen pixels covered by one shadow texel (docs/architecture.md#texel-density): the inverse
// of the texel area one pixel spans, 1 / |det J|.
float screenPixelsPerTexel(mat2 j) { return 1.0 / max(abs(determinant(j)), 1e-12); }

// Interval-based selection (seed 000, seed 004): the slice the view depth falls in. A depth
// equal to split i+1 is cascade i; there is no lower bound (below the near split is cascade 0).
int selectInterval(float vsDepth) {
    for (int i = 0; i < cascadeCount; ++i)
        if (vsDepth <= cascade[i].vsFar) return i;
    return -1;
}

// The filter's reach in cascade i's texture, uv: (taps radius + 1) texels of its own size.
vec2 edgeMargin(int i) {
    float radius = filterKind == ST_FILTER_PCF_NXN ? float(filterSize / 2) + 1.0 : 1.0;
    return radius * cascade[i].uvPerTexel.xy;
}

// Map-based selection (seed 003, seed 004): the first map whose tile holds the point, by the
// tile's bounds in its texture (the whole layer for array and textures storage).
int selectMap(vec3 wsPos, vec3 wsNormal) {
    for (int i = 0; i < cascadeCount; ++i) {
        vec2 m = edgeMargin(i);
        vec3 ts = shadowCoord(i, wsPos, wsNormal);
        vec3 lo = vec3(cascade[i].tileBounds.xy + m, 0.0);
        vec3 hi = vec3(cascade[i].tileBounds.zw - m, 1.0);
        if (all(greaterThanEqual(ts, lo)) && all(lessThanEqual(ts, hi))) return i;
    }
    return -1;
}

// Atlas taps stay inside the tile and its padding (cleared to depth 1, lit), so a tap past the
// tile's edge reads lit as it would past a separate map's edge (CLAMP_TO_BORDER), never the
// neighbouring tile. Half a texel in from the padding's outer edge, the linear filter weighs
// padding texels only; with no padding that is the tile's edge texel (CLAMP_TO_EDGE).
vec2 tapUv(int i, vec2 uv) {
    if (storage != ST_STORAGE_ATLAS) return uv;
    vec2 reach = (cascade[i].padding - 0.5) * cascade[i].uvPerTexel.xy;
    return clamp(uv, cascade[i].tileBounds.xy - reach, cascade[i].tileBounds.zw + reach);
}

// Storage "textures": GLSL 4.50 indexes an array of samplers only with a dynamically uniform
// expression, and the cascade index varies from pixel to pixel, so each case names its sampler by
// a constant. Explicit zero gradients: the call sits in non-uniform control flow, where implicit
// derivatives are undefined (the maps have one level, so the lod is 0 anyway).
float ownMapCompare(int i, vec4 p) {
    const vec2 g = vec2(0.0);
    switch (i) {
        case 0: return textureGrad(uCascadeMaps[0], p, g, g);
        case 1: return textureGrad(uCascadeMaps[1], p, g, g);
        case 2: return textureGrad(uCascadeMaps[2], p, g, g);
        case 3: return textureGrad(uCascadeMaps[3], p, g, g);
        case 4: return textureGrad(uCascadeMaps[4], p, g, g);
        case 5: return textureGrad(uCascadeMaps[5], p, g, g);
        case 6: return textureGrad(uCascadeMaps[6], p, g, g);
        case 7: return textureGrad(uCascadeMaps[7], p, g, g);
    }
    return 1.0;
}

// One compare of cascade i at uv (its texture's coordinates), nearest or 2x2 linear.
float compareNearest(int i, vec2 uv, float z) {
    if (storage == ST_STORAGE_TEXTURES) {
        // Bilinear weights at a texel's centre are (1, 0, 0, 0): the nearest texel's compare.
        vec2 t = cascade[i].uvPerTexel.xy;
        return ownMapCompare(i, vec4((floor(uv / t) + 0.5) * t, 0.0, z));
    }
    return texture(uShadowNearest, vec4(tapUv(i, uv), float(cascade[i].layer), z));
}

float compareLinear(int i, vec2 uv, float z) {
    if (storage == ST_STORAGE_TEXTURES) return ownMapCompare(i, vec4(uv, 0.0, z));
    return texture(uShadowLinear, vec4(tapUv(i, uv), float(cascade[i].layer), z));
}

// Seed 004, "Derivative-based receiver plane depth bias": depth slope per unit of shadow-map
// uv from the screen-space derivatives, dz/duv = J^-T (dz/dx, dz/dy), J = d(uv)/d(screen).
vec2 receiverPlaneSlope(vec3 ts) {
    vec3 dx = dFdx(ts);
    vec3 dy = dFdy(ts);
    mat2 j = mat2(dx.xy, dy.xy);
    float det = determinant(j);
    if (abs(det) < 1e-12) return vec2(0.0);
    return transpose(inverse(j)) * vec2(dx.z, dy.z);
}

// tan of the angle between the normal and the sun, kept finite: the slope-scaled bias grows with it.
float tanToLight(float nDotL) {
    float cosT = clamp(nDotL, 1e-3, 1.0);
    return min(sqrt(1.0 - cosT * cosT) / cosT, 10.0);
}

// Constant + slope-scaled bias, turned from metres into cascade i's depth units.
float biasedDepth(int i, float tsZ, float tanTheta) {
    float biasMetres = biasConstant + biasSlope * cascade[i].texelWorld * tanTheta;
    return min(tsZ - biasMetres / cascade[i].depthRange, 1.0);
}

// The unfiltered test: one nearest-texel compare with the bias, whatever the filter setting.
// The accuracy metrics score this against the ray-cast ground truth
// (docs/architecture.md#misclassification).
float hardShadow(int i, vec3 ts, float tanTheta) {
    return compareNearest(i, ts.xy, biasedDepth(i, ts.z, tanTheta));
}

float sampleCascade(int i, vec3 ts, vec2 dzduv, float tanTheta) {
    float z = biasedDepth(i, ts.z, tanTheta);
    if (filterKind == ST_FILTER_HARD) return compareNearest(i, ts.xy, z);
    if (filterKind == ST_FILTER_PCF2X2) return compareLinear(i, ts.xy, z);
    int r = filterSize / 2;
    float sum = 0.0;
    for (int y = -r; y <= r; ++y)
        for (int x = -r; x <= r; ++x) {
            vec2 duv = vec2(x, y) * cascade[i].uvPerTexel.xy;
            float zt = receiverPlane != 0 ? z + dot(duv, dzduv) : z;
            sum += compareLinear(i, ts.xy + duv, zt);
        }
    return sum / float((2 * r + 1) * (2 * r + 1));
}

// 0 in the cascade's interior, rising to 1 at its far end over the blend band (seed 004).
float blendWeight(int i, float vsDepth, vec3 ts) {
    if (blendBand <= 0.0 || i + 1 >= cascadeCount) return 0.0;
    float f;
    if (selection == ST_SELECT_INTERVAL) {
        f = (cascade[i].vsFar - vsDepth) / (cascade[i].vsFar - cascade[i].vsNear);
    } else {
        vec4 b = cascade[i].tileBounds;  // distance to the tile's nearest edge, in tile widths
        vec2 e = min(ts.xy - b.xy, b.zw - ts.xy) / (b.zw - b.xy);
        f = 2.0 * min(e.x, e.y);
    }
    return 1.0 - clamp(f / blendBand, 0.0, 1.0);
}

// Far-edge fade of the last cascade (as Filament's shadowFarAttenuation, Godot's fade_start,
// Unreal's FadeOutFraction): 0 before the band, 1 (fully lit) at the end of the shadow range.
float fadeWeight(int i, float vsDepth) {
    if (fadeBand <= 0.0 || i != cascadeCount - 1) return 0.0;
    float band = fadeBand * (cascade[i].vsFar - cascade[i].vsNear);
    return clamp((vsDepth - (cascade[i].vsFar - band)) / band, 0.0, 1.0);
}

ShadowResult shadowFactor(vec3 wsPos, vec3 wsNormal, float nDotL, float vsDepth) {
    int c = selection == ST_SELECT_INTERVAL ? selectInterval(vsDepth) : selectMap(wsPos, wsNormal);
    // Coordinates and derivatives for c and c+1 are computed unconditionally: derivatives are
    // only defined in uniform control flow.
    int ci = clamp(c, 0, cascadeCount - 1);
    int cn = min(ci + 1, cascadeCount - 1);
    vec3 ts = shadowCoord(ci, wsPos, wsNormal);
    vec3 tsNext = shadowCoord(cn, wsPos, wsNormal);
    vec2 slope = receiverPlaneSlope(ts);
    vec2 slopeNext = receiverPlaneSlope(tsNext);
    if (c < 0) return ShadowResult(1.0, -1);
    float tanTheta = tanToLight(nDotL);
    float f = sampleCascade(c, ts, slope, tanTheta);
    float w = blendWeight(c, vsDepth, ts);
    if (w > 0.0) f = mix(f, sampleCascade(cn, tsNext, slopeNext, tanTheta), w);
    f = mix(f, 1.0, fadeWeight(c, vsDepth));
    return ShadowResult(f, c);
}
