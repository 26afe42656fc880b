#pragma once
// When the editor redraws the scene image, and at what resolution (issue 13 #10). Pure logic:
// the app states what feeds this frame's image, the cache says whether the image on hand
// already is that image; a controller picks the interactive resolution while the camera or the
// sun moves. Tests feed both made-up inputs and frame times.
#include "renderer/render/frame_stats.h"
#include "renderer/render/side_view.h"
#include "renderer/settings/settings.h"

#include <optional>
#include <string>

namespace st::app {

// Everything the scene viewport's pixels and the picture-in-picture depend on. Not in it, as
// they are drawn over the image every frame: the A/B divider position (present() composes A's
// columns), the Accuracy overlay, the probe's readout and every panel.
struct SceneFrameInputs {
    std::string sceneKey;     // sceneKey() of the loaded scene
    int rendererGeneration = 0;  // a new Renderer (scene reload) starts from empty maps
    Settings live;            // valid settings, output size = the rendered size, view = what the
                              // main viewport shows
    std::optional<Settings> a;  // the split's A on the live view (aOnLive), while the split renders
    OrbitCamera orbit;
    int pipWidth = 0, pipHeight = 0;
    bool swapped = false;
};

bool sameFrame(const SceneFrameInputs& x, const SceneFrameInputs& y);

// Why a frame of `now` must be rendered, or "" when the image held shows exactly it.
class SceneFrameCache {
public:
    std::string check(const SceneFrameInputs& now) const;
    // The frame of `in` was rendered (or failed with these inputs: rendering them again fails the
    // same way). `stats`: the live frame's, and A's while the split is on; a cascade whose
    // redraw an update interval deferred must catch up in a later frame, so that frame is not
    // reusable.
    void rendered(const SceneFrameInputs& in, const FrameStats* live, const FrameStats* a);
    void invalidate() { held_.reset(); }

private:
    std::optional<SceneFrameInputs> held_;
    bool pending_ = false;  // some map of the held frame waits for its update interval
};

// A cascade kept this frame only because its update interval deferred the redraw.
bool mapsPending(const FrameStats& stats);

// The camera or the sun moved since the previous frame: what the interactive resolution covers.
// (A slider drag keeps full resolution: the artist is judging exactly that image.)
bool viewMoving(const Settings& previous, const Settings& now);

// The fraction of the scene viewport's width and height rendered while the view moves: from the
// wall time of the frames before, so a moving frame takes about `targetMs`. Full resolution
// again on the first frame that does not move. The scale is kept between gestures, so the next
// one starts where this one settled.
class InteractiveScale {
public:
    static constexpr double kMin = 0.25;
    static constexpr double kStep = 0.05;  // scales are multiples of this: few reallocations
    explicit InteractiveScale(double targetMs = 90.0) : targetMs_(targetMs) {}
    // Once per frame before rendering. `moving`: viewMoving(); `lastFrameMs`: the previous
    // frame's wall time. Returns the scale of this frame.
    double update(bool moving, double lastFrameMs);
    double scale() const { return scale_; }
    // The interactive maps' divisor (interactiveMaps): 2, or 4 once the smallest image scale
    // still misses the target; back to 2 when full scale has time to spare.
    int mapDivisor() const { return mapDivisor_; }

private:
    double targetMs_;
    double scale_ = 0.5;  // the first gesture's first frame; then what the last gesture settled at
    bool wasMoving_ = false;
    int mapDivisor_ = 2;
};

// The maps of an interactive frame: the preset's sizes over `divisor` (at least 256), and
// cascade i redrawn every i + 1 frames at most (up to 4). The depth pass is fill-bound on
// llvmpipe (4 x 2048 maps cost about 5x 4 x 1024 on truck_town), and every map's matrix changes
// while the camera moves.
Settings interactiveMaps(const Settings& s, int divisor = 2);

// A viewport size scaled, at least 16 pixels a side (the editor's smallest scene render).
int scaledSize(int size, double scale);

}  // namespace st::app
