// Scenario VSM light bleeding (presets/scenarios/vsm-bleeding-*, issue 12 item 3): on
// builtin:stacked-slabs the slab's umbra on the ground sees two blocker depths in one filter
// window, slats and slab. Measured against the soft truth of the sun's disc (the light-bleeding
// artifact class: too light inside a true umbra, more than k texels from its edge), VSM bleeds,
// its bleed reduction bleeds less, EVSM and MSM bleed less still.
#include "tests/metrics/scenario_gl_util.h"

namespace st {
namespace {

using test::printFigures;
using ScenarioGLTest = test::ScenarioGLTest;

struct Bleeding {
    double share = 0.0;     // light-bleeding receivers of all receivers
    double umbraLit = 0.0;  // mean filtered factor over the true umbra (t = 0) of the slab
    std::size_t pixels = 0, receivers = 0, umbra = 0;
};

// The umbra figure is the scenario's own check of the artifact class, independent of its
// k-texel rule: the mean light the filter lets into receivers the disc's truth says are dark.
Bleeding bleeding(const metrics::PresetMeasurement& m) {
    Bleeding b;
    b.pixels = m.soft.all.lightBleeding;
    b.receivers = m.soft.all.receivers;
    b.share = m.soft.all.share(m.soft.all.lightBleeding);
    double lit = 0.0;
    for (std::size_t i = 0; i < m.samples.size(); ++i) {
        if (!m.samples.receiver(i) || m.softTruth.visible[i] != 0.0f) continue;
        ++b.umbra;
        lit += m.samples.shadow[i].y;
    }
    b.umbraLit = b.umbra ? lit / double(b.umbra) : 0.0;
    return b;
}

TEST_F(ScenarioGLTest, VsmBleedsLightUnderStackedCastersAndEvsmMsmAndBleedReductionBleedLess) {
    auto run = [&](const char* name) {
        const metrics::PresetMeasurement m = measure(name);
        const Bleeding b = bleeding(m);
        printFigures("%s: light bleeding %zu of %zu receivers (%.4f), mean lit in the true umbra %.3f (%zu px), "
                     "filtered error %.4f",
                     name, b.pixels, b.receivers, b.share, b.umbraLit, b.umbra, m.soft.all.filteredError());
        return b;
    };
    const Bleeding vsm = run("vsm-bleeding-vsm");
    const Bleeding reduced = run("vsm-bleeding-vsm-reduction");
    const Bleeding evsm2 = run("vsm-bleeding-evsm2");
    const Bleeding evsm4 = run("vsm-bleeding-evsm4");
    const Bleeding msm = run("vsm-bleeding-msm");
    ASSERT_GT(vsm.umbra, 2000u) << "the slab's umbra should fill a good part of the view";
    // Control: measured 9.8 % of the receivers (5562 px, 0.53 deg, 16 rays); half of it is a
    // bleed no filter tuning hides.
    EXPECT_GT(vsm.share, 0.05);
    EXPECT_GT(vsm.umbraLit, 0.15);  // measured 0.24, the fixes 0.01..0.07
    // Fixes: each measured at least 100x below the control (README table); asserted 20x, so a
    // fix that only halves the bleeding fails.
    EXPECT_LT(reduced.share, vsm.share / 20.0);
    EXPECT_LT(evsm2.share, vsm.share / 20.0);
    EXPECT_LT(evsm4.share, vsm.share / 20.0);
    EXPECT_LT(msm.share, vsm.share / 20.0);
    EXPECT_LE(evsm4.share, evsm2.share) << "the negative warp only ever lowers the bound";
    for (const Bleeding* b : {&reduced, &evsm2, &evsm4, &msm}) EXPECT_LT(b->umbraLit, vsm.umbraLit / 2.0);
}

}  // namespace
}  // namespace st
