#pragma once
// GPU time of named passes from pairs of GL_TIMESTAMP queries. Results are read at the end of
// the frame (headless replay waits for them; llvmpipe executes synchronously anyway).
// Timestamps rather than GL_TIME_ELAPSED: llvmpipe's first TIME_ELAPSED query in a context
// reports the time since the context was created.
#include "renderer/gpu/gl.h"

#include <vector>

namespace st {

class GpuTimers {
public:
    void beginFrame(int count);           // makes sure `count` timers exist
    void begin(int index);
    void end(int index);
    double milliseconds(int index) const; // waits for the result

private:
    std::vector<gpu::Query> queries_;     // two per timer: start, end
};

}  // namespace st
