#pragma once
// The uniforms of shaders/shadow_sampling.glsl, set from one place: the main pass and the
// measurement pass must test shadows with exactly the same cascades, bias and filter.
#include "renderer/csm/cascade_plan.h"
#include "renderer/gpu/gl.h"
#include "renderer/settings/settings.h"

namespace st {

// Sets every uniform shadow_sampling.glsl declares on `program`, for the cascades of `plan`.
void setShadowUniforms(GLuint program, const Settings& s, const csm::CascadePlan& plan);

}  // namespace st
