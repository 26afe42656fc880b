// Issue 13 item 8, the accuracy rules: on measured frames of the presets that show the artifact
// (the grazing-sun scenario without bias: acne; with a normal offset far too large: peter-
// panning) the advice fires and names the knob; on default.json it stays silent.
#include "tests/metrics/metrics_gl_util.h"
#include "tests/support/gl_fixture.h"
#include "ui/advice.h"

namespace st {
namespace {

ui::AccuracyCounts toUi(const metrics::ErrorCounts& c) {
    return {c.receivers, c.falseShadowEdge, c.falseShadowGross, c.falseLightEdge, c.falseLightGross, c.filteredError()};
}

class AdviceGLTest : public test::GLTest {
protected:
    std::vector<ui::Advice> adviceFor(const Settings& s) {
        const metrics::PresetMeasurement m = test::measureStill(session, s);
        ui::AccuracyView v;
        v.state = ui::AccuracyView::State::Done;
        v.all = toUi(m.accuracy.all);
        gross = v.all;
        return ui::adviseFromAccuracy(s, v);
    }
    static const ui::Advice* find(const std::vector<ui::Advice>& advice, const std::string& rule) {
        for (const ui::Advice& a : advice)
            if (a.rule == rule) return &a;
        return nullptr;
    }
    metrics::MeasureSession session;
    ui::AccuracyCounts gross;
};

TEST_F(AdviceGLTest, AcneOnTheGrazingSunWithoutBias) {
    const auto advice = adviceFor(test::presetAtTestSize("scenarios/grazing-no-bias"));
    const ui::Advice* acne = find(advice, "acne");
    ASSERT_NE(acne, nullptr) << "false shadow gross share " << gross.share(gross.falseShadowGross);
    EXPECT_NE(acne->text.find("Raise the slope bias (0.00)"), std::string::npos) << acne->text;
    EXPECT_NE(acne->text.find("receiver-plane"), std::string::npos) << acne->text;
    EXPECT_EQ(find(advice, "peter-panning"), nullptr);
}

TEST_F(AdviceGLTest, PeterPanningWithAHugeNormalOffset) {
    Settings s = test::presetAtTestSize("scenarios/grazing-normal-offset");
    s.bias.normalOffset = 12.0f;  // texels: the shadows leave the boxes' feet
    const auto advice = adviceFor(s);
    const ui::Advice* panning = find(advice, "peter-panning");
    ASSERT_NE(panning, nullptr) << "false light gross share " << gross.share(gross.falseLightGross);
    EXPECT_NE(panning->text.find("Lower the normal offset (12.00 texels)"), std::string::npos) << panning->text;
}

TEST_F(AdviceGLTest, DefaultPresetGetsNoAccuracyAdvice) {
    const auto advice = adviceFor(test::presetAtTestSize("default"));
    EXPECT_TRUE(advice.empty()) << advice.front().text;
}

}  // namespace
}  // namespace st
