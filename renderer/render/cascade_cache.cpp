#include "renderer/render/cascade_cache.h"

#include "renderer/settings/field_table.h"

#include <algorithm>
#include <cmath>

namespace st {

int updateInterval(const Settings& s, int cascade) {
    const auto& list = s.cascades.updateInterval;
    if (cascade < 0 || std::size_t(cascade) >= list.size()) return 1;
    return std::max(1, int(std::lround(list[std::size_t(cascade)])));
}

void CascadeCache::beginFrame(const Settings& s, bool enabled) {
    ++frame_;
    forced_.clear();
    if (!enabled) {
        forced_ = "cache off";
    } else if (previous_) {
        for (const FieldInfo* f : changedFields(*previous_, s)) {
            if (f->change < ChangeClass::Reallocate) continue;
            forced_ = std::string(f->path) + " changed (" + std::string(changeClassName(f->change)) + ")";
            break;
        }
    }
    previous_ = s;
    interval_.clear();
    for (int i = 0; i < s.cascades.count; ++i) interval_.push_back(updateInterval(s, i));
    if (slots_.size() < interval_.size()) slots_.resize(interval_.size());
}

CascadeDecision CascadeCache::decide(int i, const CascadeMapKey& key) const {
    const Slot& slot = slots_[std::size_t(i)];
    if (!forced_.empty()) return {true, forced_};
    if (!slot.valid) return {true, "first frame"};
    if (key.layers != slot.key.layers || key.mapSize != slot.key.mapSize) return {true, "maps reallocated"};
    std::string why;
    if (key.viewProj != slot.key.viewProj) why = "light matrix changed";
    else if (key.casters != slot.key.casters) why = "casters changed";
    else if (key.depthClamp != slot.key.depthClamp) why = "depth clamp changed";
    else if (key.subpixelSteps != slot.key.subpixelSteps) why = "rasterizer grid changed";
    else if (key.casterNormalOffset != slot.key.casterNormalOffset) why = "caster normal offset changed";
    else return {false, "unchanged"};
    const int k = interval_[std::size_t(i)];
    const int age = frame_ - slot.drawnFrame;
    if (age < k)
        return {false, why + ", deferred: update interval " + std::to_string(k) + ", drawn " + std::to_string(age) +
                           " frame" + (age == 1 ? "" : "s") + " ago"};
    return {true, why};
}

void CascadeCache::drawn(int i, const CascadeMapKey& key, const csm::CascadeFit& fit) {
    Slot& slot = slots_[std::size_t(i)];
    slot.valid = true;
    slot.key = key;
    slot.fit = fit;
    slot.drawnFrame = frame_;
}

}  // namespace st
