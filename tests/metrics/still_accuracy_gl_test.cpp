// The editor's Accuracy panel path on a real frame: read back on the GL thread, ground truth and
// scoring on AccuracyWorker's thread. Its figures must be exactly `measure`'s for the same frame.
#include "metrics/accuracy_worker.h"
#include "tests/metrics/metrics_gl_util.h"
#include "tests/support/gl_fixture.h"

#include <chrono>
#include <thread>

namespace st {
namespace {

class StillAccuracyGLTest : public test::GLTest {};

// What EditorAccuracy::start does after the editor rendered `s`.
metrics::StillFrame editorFrame(Renderer& r, MeasurePass& pass, const Settings& s, std::shared_ptr<const Scene> scene) {
    r.render(s);
    metrics::StillFrame f;
    f.scene = std::move(scene);
    f.samples = pass.run(r, s, metrics::observerViewProj(s));
    f.plan = r.plan();
    f.mapSize = s.cascades.mapSize;
    f.cascadeCount = s.cascades.count;
    f.wsEye = s.camera.position;
    return f;
}

TEST_F(StillAccuracyGLTest, WorkerFiguresEqualMeasure) {
    Settings s = test::presetAtTestSize("default");
    s.bias.constant = 0.0f;  // acne over the open ground: plenty of errors to compare
    s.bias.slope = 0.0f;
    metrics::MeasureSession session;
    const metrics::PresetMeasurement m = test::measureStill(session, s);

    auto scene = std::make_shared<const Scene>(loadScene(s.scene, ST_PRESET_DIR));
    Renderer renderer(*scene);
    MeasurePass pass;
    metrics::AccuracyWorker worker;
    worker.submit(editorFrame(renderer, pass, s, scene));
    std::optional<metrics::AccuracyOutcome> out;
    for (int i = 0; i < 12000 && !out; ++i) {  // up to a minute
        out = worker.take();
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    ASSERT_TRUE(out) << "the job did not end";
    ASSERT_TRUE(out->result) << out->error;
    const metrics::AccuracyReport& a = out->result->report;
    EXPECT_EQ(a.classes, m.accuracy.classes);
    EXPECT_EQ(a.all.receivers, m.accuracy.all.receivers);
    EXPECT_EQ(a.all.falseShadowGross, m.accuracy.all.falseShadowGross);
    EXPECT_EQ(a.all.falseLight(), m.accuracy.all.falseLight());
    EXPECT_GT(a.all.misclassified(), 0u);
    ASSERT_EQ(a.cascades.size(), m.accuracy.cascades.size());
    for (std::size_t c = 0; c < a.cascades.size(); ++c)
        EXPECT_EQ(a.cascades[c].misclassified(), m.accuracy.cascades[c].misclassified()) << "cascade " << c;
    EXPECT_DOUBLE_EQ(a.all.filteredError(), m.accuracy.all.filteredError());
}

}  // namespace
}  // namespace st
