// tune/tune_engine.h: an engine's space moves only what the engine's knobs set, and every point it
// can reach projects onto settings the engine takes whole (nothing it lacks).
#include "renderer/export/engine_knobs.h"
#include "renderer/settings/settings.h"
#include "tune/tune_engine.h"
#include "tune/tune_space.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace st::tune {
namespace {

// Every engine with a knob table: a new table is held to these tests without a new line here.
std::vector<xport::Engine> tabledEngines() {
    std::vector<xport::Engine> out;
    for (std::size_t i = 0; i < xport::kEngineNames.size(); ++i)
        if (xport::hasKnobTable(xport::Engine(i))) out.push_back(xport::Engine(i));
    return out;
}

Settings engineBase() {
    Settings s;
    s.camera.farPlane = 400.0f;
    return s;
}

TEST(TuneEngineSpaceTest, TheSpaceMovesOnlyWhatTheEnginesKnobsSet) {
    EXPECT_GE(tabledEngines().size(), 3u);
    for (xport::Engine e : tabledEngines()) {
        const Settings base = ontoEngine(e, engineBase());
        const Space space = engineSpace(e, base);
        const std::vector<std::string> knobs = xport::engineFieldPaths(e);
        for (const Dimension& d : space.dims) {
            const std::string path = d.path.substr(0, d.path.find('['));
            EXPECT_NE(std::find(knobs.begin(), knobs.end(), path), knobs.end()) << xport::engineName(e) << ": " << d.path;
        }
    }
}

// One step along every dimension, projected as the search projects it: nothing the engine lacks.
TEST(TuneEngineSpaceTest, EveryStepProjectsOntoSettingsTheEngineTakes) {
    for (xport::Engine e : tabledEngines()) {
        const Settings base = ontoEngine(e, engineBase());
        const Space space = engineSpace(e, base);
        ASSERT_TRUE(space.project);
        int steps = 0;
        for (const Dimension& d : space.dims)
            for (std::size_t i = 0; i < d.values.size(); ++i) {
                Settings moved;
                try {
                    moved = space.project(withValue(base, d, i));
                } catch (const std::exception&) {
                    continue;  // a value the field or the engine refuses here (a split past the end)
                }
                ++steps;
                const xport::EngineKnobs k = xport::knobsFor(e, moved);
                EXPECT_TRUE(k.lacks.empty()) << xport::engineName(e) << " " << d.path << " = " << d.values[i].dump() << ": "
                                             << (k.lacks.empty() ? "" : k.lacks.front());
            }
        EXPECT_GT(steps, 20) << xport::engineName(e);
    }
}

}  // namespace
}  // namespace st::tune
