#pragma once
// GL pipeline statistics of named passes (ARB_pipeline_statistics_query): vertices and primitives
// submitted, primitives out of clipping, fragment-shader and compute-shader invocations, and
// an occlusion query (GL_SAMPLES_PASSED, active alongside them) for the samples that passed the
// depth test. Counts, not times: the same frame gives the same figures however busy the machine
// is. Like GpuTimers, one slot per pass; only one query of each target may be active at a time, so slots are begun
// and ended around passes that do not nest. Without the extension every figure stays 0.
#include "renderer/gpu/gl.h"
#include "renderer/render/pass_work.h"

#include <array>
#include <vector>

namespace st {

class PassCounters {
public:
    static constexpr int kTargets = 6;
    PassCounters();  // needs a current GL context: checks the extension

    bool supported() const { return supported_; }
    void beginFrame(int count);  // makes sure `count` slots exist; none has results yet
    void begin(int slot);
    void end(int slot);
    // The statistics of the slot's last begin/end this frame (waits for them); all 0 for a slot
    // not run this frame. Only the query fields of PassWork are set.
    PassWork read(int slot) const;

private:
    bool supported_ = false;
    std::vector<std::array<gpu::Query, kTargets>> queries_;
    std::vector<bool> ran_;
};

}  // namespace st
