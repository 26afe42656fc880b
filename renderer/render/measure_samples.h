#pragma once
// What the measurement pass reads back: per-pixel floats for the metrics (no GL here, so the
// metrics code that consumes them can be tested without a context). Rows top first, like images.
#include <glm/vec4.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace st {

struct MeasureSamples {
    int width = 0;
    int height = 0;
    std::vector<glm::vec4> position;  // ws xyz; w = 1 where a surface was drawn, 0 where none
    std::vector<glm::vec4> normal;    // ws shading normal (faces the viewer); w = N.L
    std::vector<glm::vec4> shadow;    // x unfiltered test, y filtered factor, z cascade (-1 beyond
                                      // the shadow range), w screen pixels per shadow texel
    std::vector<glm::vec4> geometry;  // the triangle's own normal on the viewer's side; w = its N.L
    // Which surface pass drew position, normal and geometry (unique in the process; 0: unknown):
    // samples with the same nonzero id have the same surfaces, so a cache keyed on them need not
    // compare the vectors (metrics/measure_session.cpp, the truth of a view).
    std::uint64_t surface = 0;
    std::size_t size() const { return std::size_t(width) * std::size_t(height); }
    bool covered(std::size_t i) const { return position[i].w > 0.0f; }
    int cascade(std::size_t i) const { return static_cast<int>(shadow[i].z); }
    // A surface facing the sun, by its shading normal (the main pass multiplies the direct light
    // by max(N.L, 0), so only there does the shadow test show) and by its triangle's normal.
    bool receiver(std::size_t i) const { return covered(i) && normal[i].w > 0.0f && geometry[i].w > 0.0f; }
    // The shadow-terminator band of smooth meshes: the shading normal faces the sun but the
    // triangle turns away from it, so rays call it self-shadowed while the image lights it
    // dimly. Neither answer is the shadow map's doing; the metrics count these pixels apart.
    bool terminator(std::size_t i) const { return covered(i) && normal[i].w > 0.0f && geometry[i].w <= 0.0f; }
};

}  // namespace st
