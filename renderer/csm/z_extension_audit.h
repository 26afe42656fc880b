#pragma once
// The z-extension audit: how far toward the sun a cascade's light box must reach beyond its
// slice so that every caster that can shadow the slice is inside it, against how far the
// preset's setting makes it reach. A caster can shadow the slice when its light-space bounds
// overlap the box in x,y and it is not entirely behind the slice (farther from the sun).
// Casters are given by their world bounds (meshes or scene nodes today; finer clusters tighten
// the answer without changing the rule).
#include "renderer/csm/geometry.h"
#include "renderer/csm/light_fit.h"
#include "renderer/settings/settings.h"

#include <span>
#include <string>

namespace st::csm {

struct ZExtensionAudit {
    float used = 0.0f;     // metres toward the sun beyond the slice's own range (+inf: pancaking)
    float minimal = 0.0f;  // the smallest extension that keeps every caster that can shadow the slice
    bool cuts = false;     // used < minimal: a caster is clipped by the near plane
};

ZExtensionAudit auditZExtension(const CascadeFit& fit, std::span<const Aabb> wsCasters, ZExtension mode);

// "cascade 2: z-extension 100 m cuts casters up to 152 m toward the sun; minimal extension 152 m"
std::string zExtensionWarning(int cascade, const ZExtensionAudit& audit);

// Metres as the warnings print them: one decimal, ".0" dropped ("152", "0.3").
std::string formatMetres(float metres);

}  // namespace st::csm
