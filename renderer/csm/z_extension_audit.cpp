#include "renderer/csm/z_extension_audit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace st::csm {

ZExtensionAudit auditZExtension(const CascadeFit& fit, std::span<const Aabb> wsCasters, ZExtension mode) {
    ZExtensionAudit a;
    const Aabb& slice = fit.lsSlice;
    // Pancaking clamps every caster in front of the box onto its near plane: none is cut.
    a.used = mode == ZExtension::Pancake ? std::numeric_limits<float>::infinity() : fit.lsBox.max.z - slice.max.z;
    for (const Aabb& ws : wsCasters) {
        const Aabb ls = transformAabb(fit.lsView, ws);
        const bool overlapsXY = ls.max.x >= fit.lsBox.min.x && ls.min.x <= fit.lsBox.max.x &&
                                ls.max.y >= fit.lsBox.min.y && ls.min.y <= fit.lsBox.max.y;
        if (!overlapsXY || ls.max.z < slice.min.z) continue;  // misses the box, or behind the slice
        a.minimal = std::max(a.minimal, ls.max.z - slice.max.z);
    }
    // Tolerance: the transformed bounds and the box are float sums of metres-sized terms.
    const float tolerance = 1e-4f * std::max(1.0f, std::abs(slice.max.z) + a.minimal);
    a.cuts = a.used + tolerance < a.minimal;
    return a;
}

std::string formatMetres(float metres) {
    char text[48];
    std::snprintf(text, sizeof text, "%.1f", double(metres));
    std::string s = text;
    if (s.size() > 2 && s.ends_with(".0")) s.resize(s.size() - 2);
    return s == "-0" ? "0" : s;
}

std::string zExtensionWarning(int cascade, const ZExtensionAudit& audit) {
    return "cascade " + std::to_string(cascade) + ": z-extension " + formatMetres(audit.used) +
           " m cuts casters up to " + formatMetres(audit.minimal) + " m toward the sun; minimal extension " +
           formatMetres(audit.minimal) + " m";
}

}  // namespace st::csm
