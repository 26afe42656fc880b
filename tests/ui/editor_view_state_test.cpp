// Camera and view are not tuning settings by accident (issue 13 #4), under ImGui's null backend.
#include "renderer/settings/settings_json.h"
#include "tests/ui/ui_driver.h"
#include "tests/ui/ui_test_data.h"

#include <gtest/gtest.h>

using namespace st;
using namespace st::test;

namespace {

class EditorViewStateTest : public ::testing::Test {
protected:
    void SetUp() override {
        d.in.stats = &stats;
        savePresetAtomic(d.s, scratch.path / "a.json");
        d.ui().setDocument(d.s, scratch.path / "a.json");
        d.frames(2);
    }
    void pickView(const char* name) {
        d.click("menu.view");
        d.click(std::string("menu.view.") + name);
    }
    FrameStats stats = fakeFrameStats();
    ScratchFolder scratch;
    UiDriver d;
};

}  // namespace

TEST_F(EditorViewStateTest, TheDebugViewIsEditorStateNotSavedAndNoUndoStep) {
    pickView("cascades");
    EXPECT_EQ(d.s.output.view, View::Cascades);  // the renderer shows it
    EXPECT_FALSE(d.ui().dirty());
    d.s.light.elevation = 30.0f;  // a real edit, so Save has something to write
    d.frame();
    d.pressKey(kKeyS, true);
    EXPECT_EQ(loadPreset(scratch.path / "a.json").output.view, View::Shaded);
    EXPECT_EQ(d.s.output.view, View::Cascades) << "saving does not change what is shown";
}

TEST_F(EditorViewStateTest, SaveViewWithPresetWritesTheViewAndCountsItAsAChange) {
    d.click("menu.view");
    d.click("menu.saveView");
    pickView("texel-density");
    EXPECT_TRUE(d.ui().dirty());
    d.pressKey(kKeyS, true);
    EXPECT_EQ(loadPreset(scratch.path / "a.json").output.view, View::TexelDensity);
}

TEST_F(EditorViewStateTest, UndoKeepsTheViewShown) {
    d.s.cascades.lambda = 0.9f;
    d.ui().recordEdit(Settings{}, d.s);
    pickView("shadow");
    d.click("presets.undo");
    EXPECT_EQ(d.s.cascades.lambda, Settings{}.cascades.lambda);
    EXPECT_EQ(d.s.output.view, View::Shadow);
}

TEST_F(EditorViewStateTest, ACameraGestureRecordedByTheAppIsOneUndoStep) {
    const Settings before = d.s;
    d.s.camera.position.x += 12.0f;  // what the app's fly camera did over a drag
    d.ui().recordEdit(before, d.s);
    d.frame();
    EXPECT_TRUE(d.ui().dirty());
    d.click("presets.undo");
    EXPECT_EQ(d.s.camera, before.camera);
    EXPECT_FALSE(d.ui().dirty());
    d.click("presets.redo");
    EXPECT_EQ(d.s.camera.position.x, before.camera.position.x + 12.0f);
}

TEST_F(EditorViewStateTest, AnimateSunIsAPreviewThatRestoresTheAzimuthUnlessKept) {
    const float start = d.s.light.azimuth;
    d.click("sun.animate");
    d.frames(30);
    EXPECT_GT(std::abs(d.s.light.azimuth - start), 1.0f);
    d.click("sun.animate");
    EXPECT_EQ(d.s.light.azimuth, start);
    EXPECT_FALSE(d.ui().dirty());
    d.click("sun.animate");
    d.frames(30);
    d.click("sun.keep");
    const float kept = d.s.light.azimuth;
    d.frames(10);
    EXPECT_EQ(d.s.light.azimuth, kept) << "kept: the animation stopped there";
    EXPECT_NE(kept, start);
    EXPECT_TRUE(d.ui().dirty());
    d.click("presets.undo");
    EXPECT_EQ(d.s.light.azimuth, start) << "keeping is one undo step";
}
