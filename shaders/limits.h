// Shared by C++ and GLSL (both preprocessors understand #define): binding points and limits.
#ifndef ST_SHADER_LIMITS_H
#define ST_SHADER_LIMITS_H

#define ST_MAX_CASCADES 8

#define ST_BINDING_SHADOW_NEAREST 0  // depth array with hardware compare, nearest: hard shadows
#define ST_BINDING_SHADOW_LINEAR 1   // same texture, linear compare: 2x2 PCF per tap
#define ST_BINDING_BASE_COLOR 2

#define ST_VIEW_SHADED 0
#define ST_VIEW_CASCADES 1
#define ST_VIEW_SHADOW 2
#define ST_VIEW_TEXEL_DENSITY 3

#define ST_FILTER_HARD 0
#define ST_FILTER_PCF2X2 1
#define ST_FILTER_PCF_NXN 2

#define ST_SELECT_INTERVAL 0
#define ST_SELECT_MAP 1

#endif
