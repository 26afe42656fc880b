#include "renderer/csm/culling.h"

namespace st::csm {

bool casterNeeded(const Aabb& wsCasterBounds, const CascadeFit& cascade, bool pancake) {
    Aabb ls = transformAabb(cascade.lsView, wsCasterBounds);
    const Aabb& box = cascade.lsBox;
    bool overlapXY = ls.max.x >= box.min.x && ls.min.x <= box.max.x && ls.max.y >= box.min.y &&
                     ls.min.y <= box.max.y;
    bool behind = ls.max.z < box.min.z;            // +Z points toward the sun
    bool inFront = ls.min.z > box.max.z && !pancake;
    return overlapXY && !behind && !inFront;
}

}  // namespace st::csm
