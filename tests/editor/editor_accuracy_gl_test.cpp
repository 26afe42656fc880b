// EditorAccuracy, the Accuracy panel's machinery, on real frames of the yard: frames are fed with
// made-up times as the editor's loop would, the worker runs for real. Once still, the panel must
// show measure's figures; a change while computing must hide everything until the new frame's
// own figures arrive.
#include "app/editor/editor_accuracy.h"
#include "metrics/figure_table.h"
#include "tests/metrics/metrics_gl_util.h"
#include "tests/support/gl_fixture.h"

#include <chrono>
#include <thread>

namespace st::app {
namespace {

using State = ui::AccuracyView::State;

class EditorAccuracyGLTest : public test::GLTest {
protected:
    // One editor frame at `now`: render, then the accuracy update, as EditorSession::frame does.
    void frame(double now, const Settings& s, bool wanted = true) {
        renderer.render(s);
        accuracy.update(now, wanted, true, renderer, s, scene);
    }
    // Still frames 1/60 s apart (while the real worker runs) until the figures are in.
    double runUntilFinished(double now, const Settings& s) {
        for (int i = 0; i < 6000 && !accuracy.finished(); ++i) {  // a minute of real time at most
            frame(now += 1.0 / 60.0, s);
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        return now;
    }
    static void expectMeasured(const ui::AccuracyView& v, const metrics::PresetMeasurement& m) {
        ASSERT_EQ(v.state, State::Done) << v.error;
        EXPECT_EQ(v.all.receivers, m.accuracy.all.receivers);
        EXPECT_EQ(v.all.misclassified(), m.accuracy.all.misclassified());
        EXPECT_EQ(v.all.gross(), m.accuracy.all.gross());
        ASSERT_EQ(v.cascades.size(), m.accuracy.cascades.size());
        for (std::size_t c = 0; c < v.cascades.size(); ++c)
            EXPECT_EQ(v.cascades[c].falseLight(), m.accuracy.cascades[c].falseLight()) << c;
        EXPECT_EQ(v.width, m.samples.width);
        // The panel's lines are the figure table's Accuracy-panel rows, in table order, with
        // measure's values for the point-truth figures.
        const auto rows = metrics::figuresShown(metrics::InEditorAccuracy);
        ASSERT_EQ(v.figures.size(), rows.size());
        for (std::size_t i = 0; i < rows.size(); ++i) {
            EXPECT_EQ(v.figures[i].key, rows[i]->key);
            EXPECT_EQ(v.figures[i].description, rows[i]->description);
            if (rows[i]->key.rfind("accuracy.", 0) == 0)
                EXPECT_EQ(v.figures[i].value, metrics::formatValue(rows[i]->unit, rows[i]->read(m))) << rows[i]->key;
        }
    }

    Settings settings = test::presetAtTestSize("default");
    std::shared_ptr<const Scene> scene = std::make_shared<const Scene>(loadScene(settings.scene, ST_PRESET_DIR));
    Renderer renderer{*scene};
    EditorAccuracy accuracy;
    metrics::MeasureSession session;
};

TEST_F(EditorAccuracyGLTest, StillFrameGetsMeasureFiguresAndAnOverlay) {
    frame(0.0, settings);
    EXPECT_EQ(accuracy.view().state, State::Settling);
    frame(0.2, settings);
    EXPECT_EQ(accuracy.view().state, State::Settling);
    frame(0.41, settings);
    EXPECT_TRUE(accuracy.view().state == State::Computing || accuracy.finished());
    // A fast job may end within that update and bring its overlay; while computing there is none.
    if (accuracy.view().state == State::Computing) EXPECT_EQ(accuracy.overlay(), 0u);
    runUntilFinished(0.41, settings);
    expectMeasured(accuracy.view(), test::measureStill(session, settings));
    EXPECT_NE(accuracy.overlay(), 0u);
}

TEST_F(EditorAccuracyGLTest, ChangeWhileComputingHidesEverythingUntilTheNewFrameIsMeasured) {
    settings.bias.constant = 0.0f;  // acne: a slow scoring pass, so the change lands mid-job
    settings.bias.slope = 0.0f;
    frame(0.0, settings);
    frame(0.5, settings);
    ASSERT_EQ(accuracy.view().state, State::Computing);
    Settings moved = settings;
    moved.camera.position.x += 1.0f;
    double now = 0.5;
    for (int i = 0; i < 20; ++i) {  // 0.33 s of moved frames: short of the settle time
        frame(now += 1.0 / 60.0, moved);
        std::this_thread::sleep_for(std::chrono::milliseconds(20));  // time for the old job to end anyway
        EXPECT_EQ(accuracy.view().state, State::Settling) << i;
        EXPECT_EQ(accuracy.overlay(), 0u) << i;
    }
    now = runUntilFinished(now, moved);
    expectMeasured(accuracy.view(), test::measureStill(session, moved));
    frame(now + 0.1, settings);  // any change drops the figures at once
    EXPECT_EQ(accuracy.view().state, State::Settling);
    EXPECT_EQ(accuracy.overlay(), 0u);
}

TEST_F(EditorAccuracyGLTest, ClosedPanelComputesNothing) {
    for (double t = 0.0; t < 2.0; t += 0.1) frame(t, settings, /*wanted=*/false);
    EXPECT_EQ(accuracy.view().state, State::Off);
    EXPECT_FALSE(accuracy.finished());
}

}  // namespace
}  // namespace st::app
