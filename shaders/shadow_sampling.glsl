// Cascade selection, biasing and filtering of the shadow-map test, from CascadeBlock
// (shaders/interface.h). The CPU twin of the selection rules is renderer/csm/selection.cpp;
// tests/metrics/selection_match_gl_test.cpp checks both pick the same cascade on every pixel.
#include "interface.h"
#include "moments.glsl"
// Storage "array" and "atlas": one depth array (the atlas is its only layer) on two samplers.
layout(binding = ST_BINDING_SHADOW_NEAREST) uniform sampler2DArrayShadow uShadowNearest;
layout(binding = ST_BINDING_SHADOW_LINEAR) uniform sampler2DArrayShadow uShadowLinear;
// Storage "textures": cascade i's own one-layer depth array on unit ST_BINDING_CASCADE_MAPS + i,
// linear compare only (one sampler per unit; the nearest test is a linear tap at a texel centre).
layout(binding = ST_BINDING_CASCADE_MAPS) uniform sampler2DArrayShadow uCascadeMaps[ST_MAX_CASCADES];
// Moment filters (array storage only, renderer/settings/validation.cpp): the filtered moments,
// one layer per cascade.
layout(binding = ST_BINDING_MOMENTS) uniform sampler2DArray uMoments;
// PCSS (array and atlas storage): the same depth texture read raw for the blocker search.
layout(binding = ST_BINDING_SHADOW_RAW) uniform sampler2DArray uShadowRaw;

struct ShadowResult {
    float factor;  // 1 lit, 0 shadowed
    int cascade;   // -1 beyond the shadow range
};

// bias.normalOffsetUnit: texels of cascade i, or metres (three.js's normalBias, shadowmap_vertex.glsl.js).
vec3 shadowCoord(int i, vec3 wsPos, vec3 wsNormal) {
    float unit = normalOffsetUnit == ST_OFFSET_METRES ? 1.0 : cascade[i].texelWorld;
    vec3 p = wsPos + wsNormal * (normalOffset * cascade[i].biasScale.z * unit);
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

// Everything the filter reads around a point in cascade i's texture, uv, in texels of its own
// size (renderer/csm/selection.h, filterPaddingTexels): NxN PCF's taps radius + 1, PCSS's capped
// radius + 1, a moment filter's blur radius + 1, else the bilinear texel.
vec2 edgeMargin(int i) {
    float radius = 1.0;
    if (filterKind == ST_FILTER_PCF_NXN) radius = float(filterSize / 2) + 1.0;
    else if (filterKind == ST_FILTER_PCSS) radius = ceil(pcssMaxRadius) + 1.0;
    else if (filterKind == ST_FILTER_VOGEL) radius = ceil(filterRadius) + 1.0;
    else if (filterKind == ST_FILTER_TENT) radius = float(filterSize / 2) + 1.0;
    else if (filterKind >= ST_FILTER_VSM && filterKind <= ST_FILTER_MSM) radius = float(blurRadius) + 1.0;
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
// expression, and the cascade index varies from pixel to pixel, so the sampler is named by a loop
// counter (uniform) and only the pixel's own cascade keeps its result. A SIMD shader without
// branches that skip (llvmpipe) issues every iteration's read: cascadeCount reads per tap, which
// renderer/csm/filter_taps.h counts. A switch over all ST_MAX_CASCADES samplers issued eight,
// whatever the count (ogldev-49's 3 maps: main pass ~25 % slower than the array's).
// Explicit zero gradients: the call sits in non-uniform control flow, where implicit derivatives
// are undefined (the maps have one level, so the lod is 0 anyway).
float ownMapCompare(int i, vec4 p) {
    const vec2 g = vec2(0.0);
    float result = 1.0;
    for (int k = 0; k < cascadeCount; ++k)
        if (k == i) result = textureGrad(uCascadeMaps[k], p, g, g);
    return result;
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

// Seed 004, "Derivative-Based Offset": the receiver's depth slope per unit of cascade i's uv,
// dz/duv = J^-T (dz/dx, dz/dy), J = d(uv)/d(screen). The screen derivatives are of the world
// position, taken once for all cascades; every cascade shares one light view (a rotation), and the
// linear part of its shadow matrix only scales that view, so this is seed 004's light-view
// derivative per cascade. Derivatives of each pixel's own texel coordinate would mix two cascades'
// coordinates in a 2x2 quad that straddles a split: the seams seed 004 warns about.
vec2 receiverPlaneSlope(int i, vec3 wsDx, vec3 wsDy) {
    mat3 m = mat3(cascade[i].shadowMatrix);
    vec3 dx = m * wsDx;
    vec3 dy = m * wsDy;
    mat2 j = mat2(dx.xy, dy.xy);
    float det = determinant(j);
    if (abs(det) < 1e-18) return vec2(0.0);
    return transpose(inverse(j)) * vec2(dx.z, dy.z);
}

// tan of the angle between the normal and the sun, kept finite: the slope-scaled bias grows with it.
float tanToLight(float nDotL) {
    float cosT = clamp(nDotL, 1e-3, 1.0);
    return min(sqrt(1.0 - cosT * cosT) / cosT, 10.0);
}

// Constant + slope-scaled bias, each times cascade i's factor (bias.constantScale, slopeScale),
// turned from metres into cascade i's depth units.
float biasedDepth(int i, float tsZ, float tanTheta) {
    vec4 k = cascade[i].biasScale;
    float constantMetres = biasUnit == ST_BIASUNIT_DEPTH ? biasConstant * cascade[i].depthRange : biasConstant;
    float biasMetres = constantMetres * k.x + biasSlope * k.y * cascade[i].texelWorld * tanTheta;
    return min(tsZ - biasMetres / cascade[i].depthRange, 1.0);
}

// The reference depth of a tap at uv, for a receiver at ts.xy of depth z: on the receiver's plane
// with receiver-plane bias, else z.
float tapDepth(vec2 uv, vec2 at, float z, vec2 dzduv) {
    return receiverPlane != 0 ? z + dot(uv - at, dzduv) : z;
}

// The unfiltered test: one nearest-texel compare with the bias, whatever the filter setting; with
// receiver-plane bias (a bias, not a filter) against the receiver's depth at that texel's centre,
// as every filter compares it. The accuracy metrics score this against the ray-cast ground truth
// (docs/architecture.md#misclassification). dzduv: receiverPlaneSlope(), or 0 without the bias.
float hardShadow(int i, vec3 ts, float tanTheta, vec2 dzduv) {
    vec2 t = cascade[i].uvPerTexel.xy;
    vec2 centre = (floor(ts.xy / t) + 0.5) * t;
    return compareNearest(i, ts.xy, tapDepth(centre, ts.xy, biasedDepth(i, ts.z, tanTheta), dzduv));
}

// One nearest compare; with receiver-plane bias against the receiver's depth at the centre of the
// texel that is read, which is where the stored depth was rasterised.
// Texels are cascade i's own (uvPerTexel: an atlas's, or a smaller per-cascade map's).
float hardTap(int i, vec2 uv, float z, vec2 dzduv) {
    vec2 t = cascade[i].uvPerTexel.xy;
    vec2 centre = (floor(uv / t) + 0.5) * t;
    return compareNearest(i, uv, tapDepth(centre, uv, z, dzduv));
}

// The 2x2 bilinear comparison. The hardware's (one reference depth for all four texels) unless
// receiver-plane bias is on: then four nearest compares, each against the receiver's depth at its
// texel's centre, blended with the same bilinear weights.
float pcf2x2(int i, vec2 uv, float z, vec2 dzduv) {
    if (receiverPlane == 0) return compareLinear(i, uv, z);
    vec2 texel = cascade[i].uvPerTexel.xy;
    vec2 t = uv / texel - 0.5;
    vec2 base = floor(t);
    vec2 f = t - base;
    vec4 s;
    for (int k = 0; k < 4; ++k) {
        vec2 c = (base + vec2(k & 1, k >> 1) + 0.5) * texel;
        s[k] = compareNearest(i, c, tapDepth(c, uv, z, dzduv));
    }
    return mix(mix(s.x, s.y, f.x), mix(s.z, s.w, f.x), f.y);
}

// One bilinear tap of a larger kernel at `tap`, for the receiver at uv: the hardware's comparison,
// or with receiver-plane bias the four texels compared each at its own centre (pcf2x2): one
// reference depth for four texels up to a texel away would bring back the acne the bias removes.
float bilinearTap(int i, vec2 tap, vec2 uv, float z, vec2 dzduv) {
    if (receiverPlane == 0) return compareLinear(i, tap, z);
    return pcf2x2(i, tap, tapDepth(tap, uv, z, dzduv), dzduv);
}

// N x N hardware-bilinear taps one texel apart, weighted by the product of the 1-D weights the CPU
// uploads (box or Gaussian, normalised: renderer/csm/filter_weights.h).
float pcfNxN(int i, vec2 uv, float z, vec2 dzduv) {
    int r = filterSize / 2;
    float sum = 0.0;
    for (int y = -r; y <= r; ++y)
        for (int x = -r; x <= r; ++x) {
            vec2 tap = uv + vec2(x, y) * cascade[i].uvPerTexel.xy;
            float w = pcfWeights[(x + r) / 4][(x + r) % 4] * pcfWeights[(y + r) / 4][(y + r) % 4];
            sum += w * bilinearTap(i, tap, uv, z, dzduv);
        }
    return sum;
}

// three.js r187 (src/renderers/shaders/ShaderChunk/shadowmap_pars_fragment.glsl.js, getShadow for
// PCFShadowMap): vogelTaps hardware-bilinear compares on a Vogel disc of `filterRadius` texels,
// rotated per pixel by interleaved gradient noise of the fragment's window position (Jimenez 2014).
// Its texel is 1 / the map's size, so the disc is in texels of cascade i's own texture.
float interleavedGradientNoise(vec2 position) {
    return fract(52.9829189 * fract(dot(position, vec2(0.06711056, 0.00583715))));
}

vec2 vogelDiskSample(int k, int n, float phi) {
    const float goldenAngle = 2.399963229728653;
    float r = sqrt((float(k) + 0.5) / float(n));
    float theta = float(k) * goldenAngle + phi;
    return vec2(cos(theta), sin(theta)) * r;
}

float pcfVogel(int i, vec2 uv, float z, vec2 dzduv) {
    vec2 radius = filterRadius * cascade[i].uvPerTexel.xy;
    float phi = interleavedGradientNoise(gl_FragCoord.xy) * 6.283185307179586;
    float sum = 0.0;
    for (int k = 0; k < vogelTaps; ++k) sum += bilinearTap(i, uv + vogelDiskSample(k, vogelTaps, phi) * radius, uv, z, dzduv);
    return sum / float(vogelTaps);
}

// Castano 2013 ("Shadow Mapping Summary, Part 1", The Witness), as Babylon.js 9.28 ships it
// (Shaders/ShadersInclude/shadowsFragmentFunctions.js computeShadowWithPCF3/5): a 3x3 or 5x5
// tent-weighted kernel from 4 or 9 hardware-bilinear compares whose offsets and weights put each
// tap's bilinear weights onto the tent. Texels are cascade i's own texture's.
float pcfTent(int i, vec2 uv, float z, vec2 dzduv) {
    vec2 t = cascade[i].uvPerTexel.xy;
    vec2 q = uv / t + 0.5;
    vec2 st = fract(q);
    vec2 base = (floor(q) - 0.5) * t;
    float sum = 0.0;
    if (filterSize <= 3) {
        vec2 w[2] = vec2[2](3.0 - 2.0 * st, 1.0 + 2.0 * st);
        vec2 o[2] = vec2[2]((2.0 - st) / w[0] - 1.0, st / w[1] + 1.0);
        for (int b = 0; b < 2; ++b)
            for (int a = 0; a < 2; ++a)
                sum += w[a].x * w[b].y * bilinearTap(i, base + vec2(o[a].x, o[b].y) * t, uv, z, dzduv);
        return sum / 16.0;
    }
    vec2 w[3] = vec2[3](4.0 - 3.0 * st, vec2(7.0), 1.0 + 3.0 * st);
    vec2 o[3] = vec2[3]((3.0 - 2.0 * st) / w[0] - 2.0, (3.0 + st) / 7.0, st / w[2] + 2.0);
    for (int b = 0; b < 3; ++b)
        for (int a = 0; a < 3; ++a)
            sum += w[a].x * w[b].y * bilinearTap(i, base + vec2(o[a].x, o[b].y) * t, uv, z, dzduv);
    return sum / 144.0;
}

// A moment filter's lit share from the filtered moments of cascade i. The footprint comes from
// the world-position derivatives (textureGrad): implicit ones are undefined in this branch.
float momentShadow(int i, vec2 uv, float z, vec3 wsDx, vec3 wsDy) {
    mat3 m = mat3(cascade[i].shadowMatrix);
    vec4 b = textureGrad(uMoments, vec3(uv, float(cascade[i].layer)), (m * wsDx).xy, (m * wsDy).xy);
    float lit;
    if (filterKind == ST_FILTER_VSM) {
        lit = chebyshevUpperBound(b.xy, z, minVariance);
    } else if (filterKind == ST_FILTER_MSM) {
        if (moments16 != 0) b = msmDequantise(b);
        lit = 1.0 - msmShadowIntensity(mix(b, vec4(0.5), momentBias), z);
    } else {
        lit = evsmLit(b, z, vec2(evsmPosExp, evsmNegExp), filterKind == ST_FILTER_EVSM4, minVariance);
    }
    // Light-bleeding reduction by remapping (Lauritzen & McCool 2008, "Layered Variance Shadow
    // Maps", sec. 4.2: linstep(amount, 1, p)); three.js cuts at 0.3 over 0.65
    // (shadowmap_pars_fragment.glsl.js:248). [0, 1] leaves the share as it is.
    lit = clamp((lit - bleedLow) / (bleedHigh - bleedLow), 0.0, 1.0);
    return pow(lit, bleedExponent);
}

// Cascade i's texels across the penumbra a blocker at depth zb casts on a receiver at depth z
// (shadow texture depths). A sun of angular diameter theta spreads a blocker's edge over
// (d_r - d_b) tan(theta) metres on a receiver d_r - d_b metres behind it along the light (the
// directional form of Fernando 2005's w = (d_r - d_b) w_light / d_b); depths are z times the
// cascade's depthRange, metres are texels times its texelWorld.
float penumbraTexels(int i, float z, float zb) {
    return (z - zb) * cascade[i].depthRange * sunTan / cascade[i].texelWorld;
}

// PCSS (Fernando 2005, "Percentage-Closer Soft Shadows"): the mean depth of the blockers found in a
// blockerTaps^2 grid over the widest penumbra possible here (a blocker at the box's sun side),
// then filterSize^2 PCF taps with the preset's weights spread over the estimated penumbra, the
// paper's w_penumbra = (d_receiver - d_blocker) * w_light / d_blocker, which for a directional
// light is (d_receiver - d_blocker) * tan(sun's angular diameter) in metres (penumbraTexels).
// Each tap is a bilinear compare whose own ramp spans one texel, so the taps span the penumbra
// less that texel: the filtered ramp then spans the estimated penumbra, as the disc's does.
// Both radii are capped at pcssMaxRadius texels (a cost bound: the cap, not the sun, sets the
// width where the penumbra is wider); a point sun (sunTan 0) leaves the 2x2 comparison.
//
// Its taps reach up to pcssMaxRadius texels from the receiver, where a constant and slope bias
// sized for one texel no longer covers a receiver tilted to the light (measured: a 32-texel kernel
// on ground at 55 deg to the sun shadowed 2 % of the lit ground beside the penumbra as acne, and
// the blocker search took that ground for blockers). So the search and the kernel compare each tap
// at the receiver's plane (seed 004's receiver-plane depth) whatever bias.receiverPlane says;
// with it off, one hardware bilinear compare per tap (the cost the cost model counts), with it on,
// each texel at its own centre (bilinearTap) as the other filters do.
float pcssTapDepth(vec2 tap, vec2 uv, float z, vec2 dzduv) { return z + dot(tap - uv, dzduv); }

float pcss(int i, vec2 uv, float z, vec2 dzduv) {
    vec2 texel = cascade[i].uvPerTexel.xy;
    float searchRadius = clamp(0.5 * penumbraTexels(i, z, 0.0), 1.0, pcssMaxRadius);
    int n = blockerTaps / 2;
    float blockers = 0.0;
    float count = 0.0;
    for (int y = -n; y <= n; ++y)
        for (int x = -n; x <= n; ++x) {
            vec2 tap = uv + vec2(x, y) * (searchRadius / float(n)) * texel;
            float d = textureLod(uShadowRaw, vec3(tapUv(i, tap), float(cascade[i].layer)), 0.0).r;
            if (d < pcssTapDepth(tap, uv, z, dzduv)) {
                blockers += d;
                count += 1.0;
            }
        }
    if (count == 0.0) return 1.0;
    float radius = clamp(0.5 * (penumbraTexels(i, z, blockers / count) - 1.0), 0.0, pcssMaxRadius);
    int r = filterSize / 2;
    float sum = 0.0;
    for (int y = -r; y <= r; ++y)
        for (int x = -r; x <= r; ++x) {
            vec2 tap = uv + vec2(x, y) * (radius / float(r)) * texel;
            float w = pcfWeights[(x + r) / 4][(x + r) % 4] * pcfWeights[(y + r) / 4][(y + r) % 4];
            sum += w * (receiverPlane != 0 ? bilinearTap(i, tap, uv, z, dzduv)
                                           : compareLinear(i, tap, pcssTapDepth(tap, uv, z, dzduv)));
        }
    return sum;
}

float sampleCascade(int i, vec3 ts, vec3 wsDx, vec3 wsDy, float tanTheta) {
    float z = biasedDepth(i, ts.z, tanTheta);
    if (filterKind >= ST_FILTER_VSM && filterKind <= ST_FILTER_MSM) return momentShadow(i, ts.xy, z, wsDx, wsDy);
    bool plane = receiverPlane != 0 || filterKind == ST_FILTER_PCSS;  // PCSS: see pcss()
    vec2 dzduv = plane ? receiverPlaneSlope(i, wsDx, wsDy) : vec2(0.0);
    if (filterKind == ST_FILTER_HARD) return hardTap(i, ts.xy, z, dzduv);
    if (filterKind == ST_FILTER_PCF2X2) return pcf2x2(i, ts.xy, z, dzduv);
    if (filterKind == ST_FILTER_PCSS) return pcss(i, ts.xy, z, dzduv);
    if (filterKind == ST_FILTER_VOGEL) return pcfVogel(i, ts.xy, z, dzduv);
    if (filterKind == ST_FILTER_TENT) return pcfTent(i, ts.xy, z, dzduv);
    return pcfNxN(i, ts.xy, z, dzduv);
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

// The factor of a surface point whose world-position screen derivatives are wsDx, wsDy: the
// measurement pass's resolve (measure_shadow.frag) passes the ones its surface pass stored.
ShadowResult shadowFactorGrad(vec3 wsPos, vec3 wsNormal, float nDotL, float vsDepth, vec3 wsDx, vec3 wsDy) {
    int c = selection == ST_SELECT_INTERVAL ? selectInterval(vsDepth) : selectMap(wsPos, wsNormal);
    int ci = clamp(c, 0, cascadeCount - 1);
    int cn = min(ci + 1, cascadeCount - 1);
    vec3 ts = shadowCoord(ci, wsPos, wsNormal);
    vec3 tsNext = shadowCoord(cn, wsPos, wsNormal);
    if (c < 0) return ShadowResult(1.0, -1);
    float tanTheta = tanToLight(nDotL);
    float f = sampleCascade(c, ts, wsDx, wsDy, tanTheta);
    float w = blendWeight(c, vsDepth, ts);
    if (w > 0.0) f = mix(f, sampleCascade(cn, tsNext, wsDx, wsDy, tanTheta), w);
    f = mix(f, 1.0, fadeWeight(c, vsDepth));
    return ShadowResult(f, c);
}

// Derivatives are only defined in uniform control flow: taken here, before any branch.
ShadowResult shadowFactor(vec3 wsPos, vec3 wsNormal, float nDotL, float vsDepth) {
    return shadowFactorGrad(wsPos, wsNormal, nDotL, vsDepth, dFdx(wsPos), dFdy(wsPos));
}
