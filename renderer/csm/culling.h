#pragma once
// Which casters a cascade needs: a caster can only darken the light box if its light-space
// bounds overlap the box in x,y and it is not entirely behind the box (farther from the sun).
// Casters entirely in front of the box (nearer the sun) are clipped by the near plane unless
// pancaking clamps them onto it, so they are kept only then.
#include "renderer/csm/geometry.h"
#include "renderer/csm/light_fit.h"

namespace st::csm {

bool casterNeeded(const Aabb& wsCasterBounds, const CascadeFit& cascade, bool pancake);

}  // namespace st::csm
