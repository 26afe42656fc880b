// The one interface between C++ and GLSL: uniform block layouts, binding points, vertex
// attribute locations (and, through codes.h, every enum code). Both languages include this file.
//
// Each block is an X-macro list of members, M(type, name) for a member and A(type, name, count)
// for an array. GLSL expands it into a std140 uniform block whose members are global names;
// C++ into a struct of the same members (st::gpu_if::FrameBlock, ...), filled on the CPU and
// uploaded as a UBO, plus a table of member names and offsets that a GL test compares with the
// driver's std140 layout. A setting reaches a shader through the field table row's `.shader`,
// which names a member here (renderer/render/shader_blocks.cpp copies it).
//
// std140 rules kept by hand, so the C++ struct needs no hidden padding: mat4/vec4 members start
// on 16 bytes (put scalars in groups of four), no vec3 (use vec4), no scalar arrays (std140 pads
// each element to 16 bytes: use a struct array), bools as int.
#ifndef ST_SHADER_INTERFACE_H
#define ST_SHADER_INTERFACE_H

#include "codes.h"

// Uniform block binding points.
#define ST_BLOCK_FRAME 0
#define ST_BLOCK_VIEW 1
#define ST_BLOCK_CASCADES 2
#define ST_BLOCK_MATERIAL 3
#define ST_BLOCK_OVERLAY 4
#define ST_BLOCK_REDUCE 5
#define ST_BLOCK_SCREEN 6    // the screen-space path's blur (renderer/render/screen_shadow.cpp)

// Texture units.
#define ST_BINDING_SHADOW_NEAREST 0  // depth array with hardware compare, nearest: hard shadows
#define ST_BINDING_SHADOW_LINEAR 1   // same texture, linear compare: 2x2 PCF per tap
#define ST_BINDING_BASE_COLOR 2
#define ST_BINDING_DEPTH_VIEW 3      // a depth array read raw (no compare) by depth_view.frag
#define ST_BINDING_REDUCE_DEPTH 4    // the camera's depth buffer, read by depth_bounds_comp.glsl
#define ST_BINDING_MOMENTS 5         // the moment array (VSM, EVSM, MSM), filtered
#define ST_BINDING_MOMENT_SOURCE 6   // the depth array read raw by moments_make.frag
#define ST_BINDING_MOMENT_SCRATCH 7  // moments blurred along x, read by moments_blur.frag

// Shader storage binding points.
#define ST_STORAGE_REDUCE 0          // depth_bounds_comp.glsl's result (renderer/render/depth_bounds_pass.cpp)

// Storage "textures": cascade i's own depth texture (a one-layer array) on unit
// ST_BINDING_CASCADE_MAPS + i, linear compare (shadow_sampling.glsl reads it through a switch).
#define ST_BINDING_CASCADE_MAPS 8
// Storage "array" and "atlas": the depth texture without compare, PCSS's blocker search (after
// the ST_MAX_CASCADES units of ST_BINDING_CASCADE_MAPS).
#define ST_BINDING_SHADOW_RAW 16
// The screen-space path (filter.screenSpace, renderer/render/screen_shadow.h): the upsampled mask
// the main and measurement passes read, and the inputs of its fullscreen passes.
#define ST_BINDING_SCREEN_SHADOW 17  // R32F, full size: the factor the image shows
#define ST_BINDING_SCREEN_SOURCE 18  // RG32F: x factor, y view depth (0: no surface)
#define ST_BINDING_SCREEN_FULL 19    // RG32F, the full-size mask: its depths guide the upsample
#define ST_BINDING_SCREEN_DEPTH 20   // D32F, the mask pass's depth: contact shadows find the surface
// The measurement pass's surfaces (renderer/render/measure_pass.h), read by measure_shadow.frag.
#define ST_BINDING_SURFACE_POSITION 21  // RGBA32F: ws position, w = 1 where a surface was drawn
#define ST_BINDING_SURFACE_NORMAL 22    // RGBA32F: ws shading normal, w = N.L
#define ST_BINDING_SURFACE_DX 23        // RGBA32F: the position's screen x derivative, w = view depth
#define ST_BINDING_SURFACE_DY 24        // RGBA32F: the position's screen y derivative

// Vertex attribute locations (renderer/render/scene_gpu.cpp, line_pass.cpp).
#define ST_ATTRIB_POSITION 0  // ws
#define ST_ATTRIB_NORMAL 1    // ws, scene vertices
#define ST_ATTRIB_UV 2        // scene vertices
#define ST_ATTRIB_COLOR 1     // line vertices

// Once per frame: the camera the cascades follow, the sun and the debug view.
#define ST_FRAME_BLOCK(M, A)                                                                      \
    M(mat4, view)      /* ws -> vs of the cascade camera: its view depth selects cascades */      \
    M(vec4, wsToSun)   /* xyz: unit vector toward the sun */                                      \
    M(float, intensity)                                                                           \
    M(float, ambient)                                                                             \
    M(int, viewMode)   /* ST_VIEW_* */                                                            \
    M(int, texelBlock) /* texel-grid view: texels per checker block */

// Per pass (and per cascade in the shadow pass): what the draws are seen through.
#define ST_VIEW_BLOCK(M, A)                                                                       \
    M(mat4, viewProj)      /* ws -> clip of this pass */                                          \
    M(int, screenShadow)   /* bool: read the factor from the screen-space mask, not the maps */   \
    M(int, subpixelSteps)  /* >0: vertices snap to 1/steps of a pixel of this pass (the engine's GPU) */ \
    M(int, viewportWidth)  /* pixels (texels) of this pass's viewport, for the snap */            \
    M(int, viewportHeight)                                                                        \
    M(float, casterNormalOffset) /* shadow pass: metres casters move into their surface x sin(N, L) */ \
    M(int, viewPad0)                                                                              \
    M(int, viewPad1)                                                                              \
    M(int, viewPad2)

// One cascade's values, an element of CascadeBlock::cascade.
#define ST_CASCADE_DATA(M, A)                                                                     \
    M(mat4, shadowMatrix)  /* ws -> ts of its texture (atlas: the tile matrix folded in) */       \
    M(vec4, tint)          /* linear RGB of the cascades view and the side view's wireframe */    \
    M(float, vsNear)       /* view depth where the slice starts, metres */                        \
    M(float, vsFar)        /* view depth where it ends, metres */                                 \
    M(float, texelWorld)   /* metres per texel */                                                 \
    M(float, depthRange)   /* metres from the light box's near to its far plane */                \
    M(vec4, tileBounds)    /* the cascade's tile in its texture, uv: x0, y0, x1, y1 */            \
    M(vec4, uvPerTexel)    /* xy: one texel of its texture in uv (atlas: 1/width, 1/height); zw 0 */\
    M(float, padding)      /* atlas: texels of lit border around the tile; else 0 */              \
    M(int, layer)          /* array layer holding it (array storage: i; else 0) */                \
    M(int, cascadeDataPad0)                                                                       \
    M(int, cascadeDataPad1)                                                                       \
    M(vec4, biasScale)     /* x, y, z: factors of biasConstant, biasSlope, normalOffset; w 0 */

// Once per frame: how every pixel picks, biases and filters its cascade.
#define ST_CASCADE_BLOCK(M, A)                                                                    \
    M(int, cascadeCount)                                                                          \
    M(int, selection)      /* ST_SELECT_* */                                                      \
    M(float, blendBand)    /* fraction of a cascade's range cross-faded into the next */          \
    M(int, filterKind)     /* ST_FILTER_* */                                                      \
    M(int, filterSize)     /* taps per side of the NxN filter */                                  \
    M(int, storage)        /* ST_STORAGE_*: where each cascade's map is sampled */                \
    M(float, biasConstant) /* metres */                                                           \
    M(float, biasSlope)    /* texels per unit tan(angle to the sun) */                            \
    M(float, normalOffset) /* texels */                                                           \
    M(int, receiverPlane)  /* bool */                                                             \
    M(float, fadeBand)     /* fraction of the last cascade's range faded to lit at its far end */ \
    M(int, filterWeights)  /* ST_WEIGHTS_* */                                                     \
    M(int, blurRadius)     /* texels each side of the moment maps' separable Gaussian blur */     \
    M(int, moments16)      /* bool: 16-bit moment storage */                                      \
    M(float, minVariance)  /* VSM/EVSM variance floor, squared depth units */                     \
    M(float, bleedExponent) /* moment filters: lit share raised to this power (seed 004) */       \
    M(float, momentBias)   /* MSM: moments pulled toward 0.5 by this share */                     \
    M(float, evsmPosExp)   /* EVSM exponents after the clamp of the storage's precision */        \
    M(float, evsmNegExp)                                                                          \
    M(int, blockerTaps)    /* PCSS: taps per side of the blocker search */                         \
    M(float, pcssMaxRadius) /* PCSS: cap of the kernel radius, texels */                          \
    M(float, sunTan)       /* tan of the sun's angular diameter (light.angularDiameter) */         \
    M(int, normalOffsetUnit) /* ST_OFFSET_*: normalOffset in texels or metres */                 \
    M(int, vogelTaps)      /* taps of the Vogel-disc filter */                                    \
    M(float, filterRadius) /* Vogel-disc filter: radius in texels */                              \
    M(int, biasUnit)       /* ST_BIASUNIT_*: biasConstant in metres or the box's normalised depth */ \
    M(float, bleedLow)     /* moment filters: lit share remapped from [bleedLow, bleedHigh] to [0, 1] */ \
    M(float, bleedHigh)                                                                           \
    A(vec4, pcfWeights, 3) /* 1-D tap weights of the NxN filter, [k/4][k%4] for tap k - size/2 */ \
    A(vec4, blurWeights, 5) /* moment blur: weight of taps +-k, [k/4][k%4], k = 0..blurRadius */  \
    A(CascadeData, cascade, ST_MAX_CASCADES)

// Per draw: the material of the draw item.
#define ST_MATERIAL_BLOCK(M, A)                                                                   \
    M(vec4, baseColor)     /* linear RGBA factor */                                               \
    M(int, hasTexture)     /* bool */                                                             \
    M(int, alphaMask)      /* bool: alpha-tested (glTF alphaMode MASK) */                         \
    M(float, alphaCutoff)                                                                         \
    M(int, materialPad0)

// Per draw of the debug passes: wireframes and shadow-map tiles.
#define ST_OVERLAY_BLOCK(M, A)                                                                    \
    M(float, brightness)   /* lines: multiplies the vertex colour */                              \
    M(int, layer)          /* depth view: the array layer shown */                                \
    M(float, depthLo)      /* depth view: stored depth shown brightest */                         \
    M(float, depthHi)      /* depth view: stored depth shown darkest */                           \
    M(vec4, uvRect)        /* depth view: the tile shown, uv in its texture: x0, y0, x1, y1 */    \
    M(int, tileBorder)     /* depth view: bool, outline the tile (the atlas image) */             \
    M(int, overlayPad0)                                                                           \
    M(int, overlayPad1)                                                                           \
    M(int, overlayPad2)                                                                           \
    M(vec4, depthPlane)    /* depth view: x u + y v + z, the tile's mean depth plane (uv 0..1) */

// The depth-bounds reduction (depth_bounds_comp.glsl): how a depth texel becomes a sample.
#define ST_REDUCE_BLOCK(M, A)                                                                     \
    M(mat4, reduceInvProj)  /* camera clip -> vs */                                               \
    M(mat4, reduceVsToLs)   /* vs -> light view (ls) */                                           \
    A(vec4, reduceSplits, 3) /* split depths 0..count, four per vec4 */                           \
    M(int, reduceMode)      /* 0: depth range; 1: and ls bounds per cascade */                    \
    M(int, reduceCascades)  /* cascades to reduce in mode 1 */                                    \
    M(int, reduceWidth)     /* depth texture size, texels */                                      \
    M(int, reduceHeight)

// The screen-space path's passes (seed 001: downsample, horizontal blur, vertical blur, upsample).
#define ST_SCREEN_BLOCK(M, A)                                                                     \
    A(vec4, screenWeights, 5) /* 1-D Gaussian weights of taps 0..radius, [k/4][k%4], sum(-r..r) 1 */\
    M(int, screenRadius)      /* taps each side */                                                \
    M(int, screenAxis)        /* 0: blur along x, 1: along y */                                   \
    M(int, screenDownsample)  /* N: the blurred mask is 1/N of the full size */                   \
    M(float, screenDepthSigma) /* depth-aware weight, fraction of the view depth; 0 = off */     \
    M(mat4, contactViewProj)   /* contact shadows: ws -> clip of the mask's camera */             \
    M(mat4, contactClipToWs)   /* its inverse */                                                  \
    M(vec4, contactToSun)      /* xyz: unit vector toward the sun */                              \
    M(float, contactLength)    /* metres marched toward the sun */                                \
    M(int, contactSteps)       /* depth-buffer samples along the march */                         \
    M(float, contactThickness) /* metres behind the depth buffer a sample still counts as hit */  \
    M(int, contactUseMask)     /* 1: combine with the mask's own factor (no blur ran) */

#ifdef __cplusplus
// ---------------------------------------------------------------------------------------------
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstddef>
#include <string_view>
#include <type_traits>

namespace st::gpu_if {

// std140 aligns mat4 and vec4 to 16 bytes; glm's types align to 4.
typedef glm::mat4 mat4 __attribute__((aligned(16)));
typedef glm::vec4 vec4 __attribute__((aligned(16)));

#define ST_CPP_MEMBER(type, name) type name{};
#define ST_CPP_ARRAY(type, name, count) type name[count]{};
struct alignas(16) CascadeData { ST_CASCADE_DATA(ST_CPP_MEMBER, ST_CPP_ARRAY) };
struct alignas(16) FrameBlock { ST_FRAME_BLOCK(ST_CPP_MEMBER, ST_CPP_ARRAY) };
struct alignas(16) ViewBlock { ST_VIEW_BLOCK(ST_CPP_MEMBER, ST_CPP_ARRAY) };
struct alignas(16) CascadeBlock { ST_CASCADE_BLOCK(ST_CPP_MEMBER, ST_CPP_ARRAY) };
struct alignas(16) MaterialBlock { ST_MATERIAL_BLOCK(ST_CPP_MEMBER, ST_CPP_ARRAY) };
struct alignas(16) OverlayBlock { ST_OVERLAY_BLOCK(ST_CPP_MEMBER, ST_CPP_ARRAY) };
struct alignas(16) ReduceBlock { ST_REDUCE_BLOCK(ST_CPP_MEMBER, ST_CPP_ARRAY) };
struct alignas(16) ScreenBlock { ST_SCREEN_BLOCK(ST_CPP_MEMBER, ST_CPP_ARRAY) };
#undef ST_CPP_MEMBER
#undef ST_CPP_ARRAY

// What a scalar member holds, so a setting is copied into it with the right type.
enum class MemberType { Float, Int, Other };

struct MemberInfo {
    std::string_view name;
    std::size_t offset;  // bytes from the start of the block
    std::size_t size;    // bytes
    MemberType type;
};

template <class T>
constexpr MemberType memberType() {
    if constexpr (std::is_same_v<T, float>) return MemberType::Float;
    else if constexpr (std::is_same_v<T, int>) return MemberType::Int;
    else return MemberType::Other;
}

#define ST_INFO_M(type, name) MemberInfo{#name, offsetof(B, name), sizeof(B::name), memberType<type>()},
#define ST_INFO_A(type, name, count) MemberInfo{#name, offsetof(B, name), sizeof(B::name), MemberType::Other},

// Member tables in declaration order; the last element is a sentinel with an empty name.
template <class B>
struct BlockMembers;
#define ST_BLOCK_MEMBERS(Block, LIST)                                                             \
    template <>                                                                                   \
    struct BlockMembers<Block> {                                                                  \
        using B = Block;                                                                          \
        static constexpr std::string_view blockName = #Block;                                     \
        static constexpr MemberInfo members[] = {LIST(ST_INFO_M, ST_INFO_A) MemberInfo{}};        \
    };
ST_BLOCK_MEMBERS(FrameBlock, ST_FRAME_BLOCK)
ST_BLOCK_MEMBERS(ViewBlock, ST_VIEW_BLOCK)
ST_BLOCK_MEMBERS(CascadeData, ST_CASCADE_DATA)
ST_BLOCK_MEMBERS(CascadeBlock, ST_CASCADE_BLOCK)
ST_BLOCK_MEMBERS(MaterialBlock, ST_MATERIAL_BLOCK)
ST_BLOCK_MEMBERS(OverlayBlock, ST_OVERLAY_BLOCK)
ST_BLOCK_MEMBERS(ReduceBlock, ST_REDUCE_BLOCK)
ST_BLOCK_MEMBERS(ScreenBlock, ST_SCREEN_BLOCK)
#undef ST_BLOCK_MEMBERS
#undef ST_INFO_M
#undef ST_INFO_A

}  // namespace st::gpu_if

#else
// ---------------------------------------------------------------------------------------------
#define ST_GLSL_MEMBER(type, name) type name;
#define ST_GLSL_ARRAY(type, name, count) type name[count];
struct CascadeData { ST_CASCADE_DATA(ST_GLSL_MEMBER, ST_GLSL_ARRAY) };
layout(std140, binding = ST_BLOCK_FRAME) uniform FrameBlock { ST_FRAME_BLOCK(ST_GLSL_MEMBER, ST_GLSL_ARRAY) };
layout(std140, binding = ST_BLOCK_VIEW) uniform ViewBlock { ST_VIEW_BLOCK(ST_GLSL_MEMBER, ST_GLSL_ARRAY) };
layout(std140, binding = ST_BLOCK_CASCADES) uniform CascadeBlock { ST_CASCADE_BLOCK(ST_GLSL_MEMBER, ST_GLSL_ARRAY) };
layout(std140, binding = ST_BLOCK_MATERIAL) uniform MaterialBlock { ST_MATERIAL_BLOCK(ST_GLSL_MEMBER, ST_GLSL_ARRAY) };
layout(std140, binding = ST_BLOCK_OVERLAY) uniform OverlayBlock { ST_OVERLAY_BLOCK(ST_GLSL_MEMBER, ST_GLSL_ARRAY) };
layout(std140, binding = ST_BLOCK_REDUCE) uniform ReduceBlock { ST_REDUCE_BLOCK(ST_GLSL_MEMBER, ST_GLSL_ARRAY) };
layout(std140, binding = ST_BLOCK_SCREEN) uniform ScreenBlock { ST_SCREEN_BLOCK(ST_GLSL_MEMBER, ST_GLSL_ARRAY) };
#undef ST_GLSL_MEMBER
#undef ST_GLSL_ARRAY
#endif

#endif
