// Enum codes and limits, read by C++ (renderer/settings/settings.h defines each enum's values
// from these) and by GLSL (through shaders/interface.h). Plain #defines only: no GLM, no types,
// so the installed cascade math can carry it. A code is an enumerator's value and its index in
// the enum's name table; each *_COUNT is checked against that table by a static_assert.
#ifndef ST_SHADER_CODES_H
#define ST_SHADER_CODES_H

#define ST_MAX_CASCADES 8

// SplitScheme
#define ST_SPLIT_UNIFORM 0
#define ST_SPLIT_LOGARITHMIC 1
#define ST_SPLIT_PRACTICAL 2
#define ST_SPLIT_MANUAL 3
#define ST_SPLIT_COUNT 4

// FitMode
#define ST_FIT_CASCADE 0
#define ST_FIT_SCENE 1
#define ST_FIT_SPHERE 2
#define ST_FIT_SAMPLES 3
#define ST_FIT_DIAGONAL 4  /* a square as wide as the slice's longer diagonal (three.js CSM) */
#define ST_FIT_COUNT 5

// ZExtension
#define ST_ZEXT_NONE 0
#define ST_ZEXT_DISTANCE 1
#define ST_ZEXT_SCENE_BOUNDS 2
#define ST_ZEXT_PANCAKE 3
#define ST_ZEXT_COUNT 4

// DepthBounds
#define ST_DEPTH_BOUNDS_OFF 0
#define ST_DEPTH_BOUNDS_FIT 1
#define ST_DEPTH_BOUNDS_COUNT 2

// Selection
#define ST_SELECT_INTERVAL 0
#define ST_SELECT_MAP 1
#define ST_SELECT_COUNT 2

// FilterKind
#define ST_FILTER_HARD 0
#define ST_FILTER_PCF2X2 1
#define ST_FILTER_PCF_NXN 2
#define ST_FILTER_VSM 3    /* moment filters (renderer/render/moment_maps.h): VSM..MSM */
#define ST_FILTER_EVSM2 4
#define ST_FILTER_EVSM4 5
#define ST_FILTER_MSM 6
#define ST_FILTER_PCSS 7   /* percentage-closer soft shadows: blocker search, then PCF */
#define ST_FILTER_VOGEL 8  /* bilinear compares on a Vogel disc rotated per pixel (three.js r182+) */
#define ST_FILTER_TENT 9   /* a tent-weighted NxN kernel from bilinear compares (Castano 2013; Babylon.js PCF3/PCF5) */
#define ST_FILTER_COUNT 10

// CasterFaces: which faces of single-sided materials the shadow pass draws (double-sided: both)
#define ST_FACES_BOTH 0
#define ST_FACES_BACK 1
#define ST_FACES_FRONT 2
#define ST_FACES_COUNT 3

// Snap: how a stabilized light box moves onto the texel grid
#define ST_SNAP_BOX_FLOOR 0     /* its min corner floored, the texel size / (m - 1) (seed 001) */
#define ST_SNAP_CENTRE_FLOOR 1  /* its centre floored to texels of size / m (three.js CSM) */
#define ST_SNAP_CENTRE_ROUND 2  /* its centre rounded to texels of size / m (Babylon.js CSM) */
#define ST_SNAP_COUNT 3

/* SliceCorners (cascades.sliceCorners): where a fit finds the slice's corners */
#define ST_CORNERS_EXACT 0            /* from the camera's planes, in float (renderer/csm/frustum.cpp) */
#define ST_CORNERS_FLOAT32_INVERSE 1  /* through a float32-stored inverse view-projection (Babylon.js) */
#define ST_CORNERS_COUNT 2

/* SphereCentre (cascades.sphereCentre): where the sphere fit centres each slice's sphere */
#define ST_SPHERE_SMALLEST 0      /* the smallest sphere around the slice, on the view axis */
#define ST_SPHERE_CORNERS_MEAN 1  /* the mean of the slice's 8 corners (Babylon.js, Godot) */
#define ST_SPHERE_COUNT 2

// BiasUnit: what bias.constant counts
#define ST_BIASUNIT_METRES 0
#define ST_BIASUNIT_DEPTH 1     /* the light box's normalised depth (its near..far plane as 0..1) */
#define ST_BIASUNIT_COUNT 2

// OffsetUnit: what bias.normalOffset counts
#define ST_OFFSET_TEXELS 0
#define ST_OFFSET_METRES 1
#define ST_OFFSET_COUNT 2

/* NormalOffsetSide (bias.normalOffsetSide): what the normal offset moves */
#define ST_NORMALSIDE_RECEIVER 0    /* the receiver, out along its normal, by the offset */
#define ST_NORMALSIDE_CASTER_SIN 1  /* the caster, into its surface, by the offset x sin(N, L) (Babylon.js) */
#define ST_NORMALSIDE_COUNT 2

// FilterWeights: the weights of the NxN PCF taps
#define ST_WEIGHTS_BOX 0
#define ST_WEIGHTS_GAUSSIAN 1
#define ST_WEIGHTS_COUNT 2

// ScreenSpace: seed 001's screen-space path (renderer/render/screen_shadow.h): the filter's
// factor drawn into a mask at full resolution, downsampled, blurred, upsampled, read by the main pass
#define ST_SCREEN_OFF 0
#define ST_SCREEN_BLUR 1
#define ST_SCREEN_COUNT 2

// ContactShadows: a short screen-space march toward the sun through the camera's depth near each
// receiver, its factor combined with the map's (renderer/render/screen_shadow.h; Godot PR #118045)
#define ST_CONTACT_OFF 0
#define ST_CONTACT_MARCH 1
#define ST_CONTACT_COUNT 2

// CascadeStorage: one depth array layer per cascade; one atlas texture with a tile per cascade
// (seed 003); one texture per cascade (seed 002)
#define ST_STORAGE_ARRAY 0
#define ST_STORAGE_ATLAS 1
#define ST_STORAGE_TEXTURES 2
#define ST_STORAGE_COUNT 3

// View (Side draws the shaded scene from the orbit camera: main.frag shades it as SHADED)
#define ST_VIEW_SHADED 0
#define ST_VIEW_CASCADES 1
#define ST_VIEW_SHADOW 2
#define ST_VIEW_TEXEL_DENSITY 3
#define ST_VIEW_SIDE 4
#define ST_VIEW_TEXEL_GRID 5  // seed 003: each map filled with a checker of output.texelBlock texels
#define ST_VIEW_COUNT 6

#endif
