#pragma once
// The uniform blocks of shaders/interface.h filled from Settings and the cascade plan: computed
// once on the CPU (no cascade math in shaders), uploaded by the passes. No GL calls here.
#include "renderer/csm/cascade_plan.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"
#include "shaders/interface.h"

#include <span>

namespace st {

// Copies every field-table row whose `.shader` names a member of `members` into that member
// of the block at `block` (float fields into float members; int, bool and enum fields into int
// members as their shader code). A row naming a member of another type is a programming error:
// std::logic_error.
void copyShaderFields(const Settings& s, std::span<const gpu_if::MemberInfo> members, void* block);

template <class Block>
void copyShaderFields(const Settings& s, Block& block) {
    copyShaderFields(s, gpu_if::BlockMembers<Block>::members, &block);
}

gpu_if::FrameBlock frameBlock(const Settings& s, const csm::CascadePlan& plan);
gpu_if::CascadeBlock cascadeBlock(const Settings& s, const csm::CascadePlan& plan);
// The EVSM exponent used: `requested` clamped so the warped moments fit the storage's floats.
float evsmExponent(float requested, bool sixteenBit);
gpu_if::MaterialBlock materialBlock(const Material& m, bool textured);

}  // namespace st
