#pragma once
// Which cascade maps to redraw this frame (issue 11 item 3). A map is redrawn only when what it
// holds would change: its light matrix, its set of casters, the depth clamp, or a setting whose
// change class (the field table) reallocates the maps or more. So a still camera redraws
// nothing, and with stable fit a small move redraws only the cascades whose snapped matrix
// moved. cascades.updateInterval[i] = k lets a changed cascade wait until k frames have passed
// since its last redraw; it is then sampled with the matrix it was drawn with. No GL.
#include "renderer/csm/light_fit.h"
#include "renderer/settings/settings.h"

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace st {

// Everything a cascade's map content depends on, besides the scene.
struct CascadeMapKey {
    glm::mat4 viewProj{1.0f};
    bool depthClamp = false;
    std::uint64_t casters = 0;  // DrawBatches::hash() of the clusters drawn
    int layers = 0;             // of the map storage
    int mapSize = 0;
    int casterFaces = 0;        // CasterFaces: which faces were drawn
    int subpixelSteps = 0;      // RenderOptions::subpixelSteps: the grid vertices were snapped to
    float casterNormalOffset = 0.0f;  // metres the casters were moved into their surface
    bool operator==(const CascadeMapKey&) const = default;
};

struct CascadeDecision {
    bool redraw = true;
    std::string reason;  // "first frame", "light matrix changed", "unchanged", ...
};

class CascadeCache {
public:
    // Starts a frame of settings `s`: compares them with the previous frame's through the field
    // table, so a reallocating change redraws every map. enabled = false: every map every frame.
    void beginFrame(const Settings& s, bool enabled);
    // What to do with cascade i, whose map would now be drawn with `key`.
    CascadeDecision decide(int i, const CascadeMapKey& key) const;
    // Cascade i was redrawn with `key` and `fit` (kept for sampling while an interval defers).
    void drawn(int i, const CascadeMapKey& key, const csm::CascadeFit& fit);
    // The fit cascade i's map holds (the one given to drawn()); only valid after it.
    const csm::CascadeFit& heldFit(int i) const { return slots_[std::size_t(i)].fit; }
    void invalidate() { slots_.clear(); previous_.reset(); }
    int frame() const { return frame_; }

private:
    struct Slot {
        bool valid = false;
        CascadeMapKey key;
        csm::CascadeFit fit;
        int drawnFrame = 0;
    };
    std::vector<Slot> slots_;
    std::optional<Settings> previous_;
    std::string forced_;  // non-empty: every map is redrawn this frame, for this reason
    std::vector<int> interval_;
    int frame_ = -1;
};

// cascades.updateInterval[i] as frames, 1 where the list has no entry.
int updateInterval(const Settings& s, int cascade);

}  // namespace st
