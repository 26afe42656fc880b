#pragma once
// The fixture of the scenario tests (presets/scenarios/README.md): a scenario preset at test
// size, measured still or along its path, with its figures printed for the README's table.
#include "tests/metrics/metrics_gl_util.h"
#include "tests/support/gl_fixture.h"

#include <cstdio>
#include <string>

namespace st::test {

inline Settings scenario(const std::string& name) { return presetAtTestSize("scenarios/" + name); }

class ScenarioGLTest : public GLTest {
public:
    metrics::PresetMeasurement measure(const Settings& s) {
        last_ = s;
        return measureStill(session_, s);
    }
    metrics::PresetMeasurement measure(const std::string& name) { return measure(scenario(name)); }
    metrics::DensityReport measureDensity(const Settings& s) { return measure(s).density; }
    // Cascade 0's texel size in metres in the plan of the last preset measured.
    float cascadeZeroTexel() { return session_.entryFor(last_, ST_PRESET_DIR).renderer->plan().cascades.at(0).texelWorldSize; }
    metrics::FlickerReport flicker(const Settings& s) {
        auto& e = session_.entryFor(s, ST_PRESET_DIR);
        return metrics::measureFlicker(*e.renderer, session_.pass(), s);
    }
protected:
    metrics::MeasureSession session_;
    Settings last_;
};

// One line of figures per measured preset in the test's output (the README's values).
template <class... A>
void printFigures(const char* format, A... args) {
    std::printf("[ figures  ] ");
    std::printf(format, args...);
    std::printf("\n");
}

}  // namespace st::test
