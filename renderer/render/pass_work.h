#pragma once
// The work one pass did, counted rather than timed, so it is identical in every run of the same
// settings whatever else the machine is doing: GL pipeline statistics queries
// (ARB_pipeline_statistics_query), an occlusion query and the renderer's own counts. llvmpipe
// counts fragment-shader invocations before the depth test, the same in any draw order; the
// samples that passed it show overdraw (what llvmpipe actually shades). The cost model
// (metrics/cost_model.h) turns these into modelled milliseconds. Plain data, no GL.
#include <cstdint>
#include <vector>

namespace st {

struct PassWork {
    std::uint64_t draws = 0;               // draw commands (each command of a multi-draw counts)
    std::uint64_t vertices = 0;            // GL_VERTICES_SUBMITTED_ARB
    std::uint64_t primitives = 0;          // GL_PRIMITIVES_SUBMITTED_ARB
    std::uint64_t clippedPrimitives = 0;   // GL_CLIPPING_OUTPUT_PRIMITIVES_ARB: what reached the rasteriser
    std::uint64_t fragments = 0;           // GL_FRAGMENT_SHADER_INVOCATIONS_ARB
    std::uint64_t samplesPassed = 0;       // GL_SAMPLES_PASSED: fragments that passed the depth test (what llvmpipe shades)
    std::uint64_t computeInvocations = 0;  // GL_COMPUTE_SHADER_INVOCATIONS_ARB
    std::uint64_t texelsCleared = 0;       // render-target texels cleared (maps and targets)
    std::uint64_t filterTaps = 0;          // shadow-map samples the pass's shading took (taps per shaded fragment x fragments)
    std::uint64_t bytesRead = 0;           // of shadow and filter maps
    std::uint64_t bytesWritten = 0;        // of shadow and filter maps

    PassWork& operator+=(const PassWork& o) {
        draws += o.draws, vertices += o.vertices, primitives += o.primitives;
        clippedPrimitives += o.clippedPrimitives, fragments += o.fragments, samplesPassed += o.samplesPassed;
        computeInvocations += o.computeInvocations, texelsCleared += o.texelsCleared;
        filterTaps += o.filterTaps, bytesRead += o.bytesRead, bytesWritten += o.bytesWritten;
        return *this;
    }
    bool operator==(const PassWork&) const = default;
};

// One frame's work by pass, the grouping the timers use (FrameStats::gpu*Ms).
struct FrameWork {
    std::vector<PassWork> cascades;  // each cascade's depth pass; all zero for a map that was kept
    PassWork shadow;                 // the sum of the cascades
    PassWork main;                   // the main (or side) pass
    PassWork filter;                 // the filter's extra passes: moment maps and blur, the screen-space path
    PassWork depthBounds;            // depth prepass and reduction
    bool operator==(const FrameWork&) const = default;
};

}  // namespace st
