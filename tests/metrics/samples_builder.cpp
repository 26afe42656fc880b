#include "tests/metrics/samples_builder.h"

namespace st::test {

MeasureSamples floorSamples(int width, int height) {
    MeasureSamples s;
    s.width = width;
    s.height = height;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            s.position.emplace_back(float(x), 0.0f, float(y), 1.0f);
            s.normal.emplace_back(0.0f, 1.0f, 0.0f, 1.0f);
            s.shadow.emplace_back(1.0f, 1.0f, 0.0f, 1.0f);
            s.geometry.emplace_back(0.0f, 1.0f, 0.0f, 1.0f);
        }
    }
    return s;
}

void setMap(MeasureSamples& s, int x, int y, float hard, float filtered) {
    glm::vec4& v = s.shadow[std::size_t(y) * s.width + x];
    v.x = hard;
    v.y = filtered;
}

}  // namespace st::test
