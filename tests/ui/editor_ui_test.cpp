// EditorUi behaviour with scripted mouse and keys under ImGui's null backend (no window, no GL):
// the widgets come from the field table, edits are clamped, undo merges a drag, presets load and
// save through the panel, problems are shown instead of thrown.
#include "renderer/settings/settings_json.h"
#include "renderer/settings/validation.h"
#include "ui/field_rules.h"
#include "tests/ui/ui_driver.h"
#include "tests/ui/ui_test_data.h"

#include <gtest/gtest.h>

#include <cstdint>

using namespace st;
using namespace st::test;

namespace {

class EditorUiTest : public ::testing::Test {
protected:
    void SetUp() override {
        d.in.stats = &stats;
        d.frames(2);  // windows appear, rectangles are recorded
    }
    // Drags the elevation slider from its middle (0 deg) to 90 % of its width.
    float dragElevation() {
        const auto r = d.rect("light.elevation");
        d.drag(r.at(0.5f, 0.5f), r.at(0.9f, 0.5f));
        return d.s.light.elevation;
    }
    static ImTextureID fakeTexture(int n) { return reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(n)); }

    FrameStats stats = fakeFrameStats();
    ScratchFolder scratch;
    UiDriver d;
};

}  // namespace

TEST_F(EditorUiTest, EveryFieldOfTheOpenGroupsHasAWidget) {
    for (const FieldInfo& field : fieldTable()) {
        const std::string group(field.path.substr(0, field.path.find('.')));
        const bool closedGroup = field.path.find('.') != std::string_view::npos &&
                                 group != "camera" && group != "light" && group != "cascades" &&
                                 group != "filter" && group != "bias";
        // Lists record their elements' rects; empty by default, they show only an Add button.
        if (closedGroup || field.debug || field.path == "cascades.manualSplits" || field.path == "cascades.updateInterval") continue;
        EXPECT_TRUE(d.drawn(field.path)) << field.path;
    }
    EXPECT_FALSE(d.drawn("output.width"));  // collapsed by default
    d.scroll(d.rect("light.elevation").center(), -30.0f);  // the Output header is below the fold
    d.click("group.output");
    EXPECT_TRUE(d.drawn("output.width"));
    EXPECT_TRUE(d.drawn("output.view"));
}

// The late-matrices knob exists only to show three.js #30053's flicker: it sat among the Cascades
// knobs an artist tunes. The table's debug rows are drawn under a "Debug" heading, closed.
TEST_F(EditorUiTest, DebugKnobsSitUnderAClosedDebugHeadingNotInTheirGroup) {
    const FieldInfo* late = findField("cascades.matricesOneFrameLate");
    ASSERT_NE(late, nullptr);
    EXPECT_TRUE(late->debug);
    ASSERT_TRUE(d.drawn("cascades.fitFovY")) << "the Cascades group is open";
    EXPECT_FALSE(d.drawn("cascades.matricesOneFrameLate")) << "drawn in the Cascades group";
    d.scroll(d.rect("light.elevation").center(), -60.0f);  // the Debug heading is the last group
    ASSERT_TRUE(d.drawn("group.debug"));
    EXPECT_GT(d.rect("group.debug").min.y, d.rect("group.output").min.y) << "after every other group";
    for (const FieldInfo& field : fieldTable())
        if (field.debug) EXPECT_FALSE(d.drawn(field.path)) << field.path << ": the Debug heading starts closed";
    d.click("group.debug");
    d.frame();
    for (const FieldInfo& field : fieldTable())
        if (field.debug) EXPECT_TRUE(d.drawn(field.path)) << field.path;
    d.click("cascades.matricesOneFrameLate");  // a checkbox: edits through the table as any row
    EXPECT_TRUE(d.s.cascades.matricesOneFrameLate);
    EXPECT_TRUE(d.ui().dirty());
}

TEST_F(EditorUiTest, ManualSplitsAppearForTheManualSchemeWithCountMinusOneEntries) {
    EXPECT_FALSE(d.drawn("cascades.manualSplits[0]"));
    d.s.cascades.scheme = SplitScheme::Manual;
    d.frame();
    EXPECT_EQ(d.s.cascades.manualSplits, (std::vector<float>{6.2f, 24.5f, 92.0f}));  // seeded from the renderer
    EXPECT_TRUE(d.drawn("cascades.manualSplits[2]"));
    EXPECT_TRUE(d.last.settingsValid);
    d.s.cascades.count = 2;
    d.frame();
    EXPECT_EQ(d.s.cascades.manualSplits.size(), 1u);
    EXPECT_FALSE(d.drawn("cascades.manualSplits[1]"));
}

TEST_F(EditorUiTest, DraggingASliderEditsThroughTheTableAndReportsTheChange) {
    const float before = d.s.light.elevation;
    const auto r = d.rect("light.elevation");
    d.mouse(r.at(0.5f, 0.5f), false);
    d.frame();
    d.mouse(r.at(0.5f, 0.5f), true);
    d.frame();
    d.mouse(r.at(0.8f, 0.5f), true);
    d.frame();
    EXPECT_GT(d.s.light.elevation, before);
    EXPECT_EQ(d.last.change, ChangeClass::Uniform);
    d.mouse(r.at(0.8f, 0.5f), false);
    d.frame();
    EXPECT_EQ(d.last.change, ChangeClass::None);
    EXPECT_TRUE(d.ui().dirty());
    EXPECT_EQ(d.ui().windowTitle(), "shadowtune - untitled *");
}

TEST_F(EditorUiTest, UndoRevertsAWholeDragAndRedoReappliesIt) {
    const float before = d.s.light.elevation;
    const float dragged = dragElevation();
    ASSERT_GT(dragged, before + 10.0f);
    d.pressKey(kKeyZ, true);
    EXPECT_EQ(d.s.light.elevation, before) << "one Ctrl+Z undoes the whole drag, not one frame of it";
    EXPECT_EQ(d.last.change, ChangeClass::None);  // the change was reported by the frame that undid it
    EXPECT_FALSE(d.ui().dirty());
    d.pressKey(kKeyZ, true, true);
    EXPECT_EQ(d.s.light.elevation, dragged);
    d.pressKey(kKeyZ, true);
    d.pressKey(kKeyZ, true);  // nothing more to undo: no change, no crash
    EXPECT_EQ(d.s.light.elevation, before);
}

// Issue 13 #7: lambda 5 used to become 1 and count 12 become 8 without a word.
TEST_F(EditorUiTest, TypedValuesOutsideTheRangeAreRefusedWithTheRangeNotClamped) {
    const float lambda = d.s.cascades.lambda;
    d.ctrlClick(d.rect("cascades.lambda").center());  // Ctrl+click turns a slider into a text field
    d.typeText("5");
    d.pressKey(kKeyEnter);
    EXPECT_EQ(d.s.cascades.lambda, lambda);
    ASSERT_TRUE(d.drawn("cascades.lambda#refused"));
    d.ctrlClick(d.rect("cascades.count").center());
    d.typeText("12");
    d.pressKey(kKeyEnter);
    EXPECT_EQ(d.s.cascades.count, 4);
    EXPECT_TRUE(d.drawn("cascades.count#refused"));
    EXPECT_TRUE(d.last.settingsValid);
    d.ctrlClick(d.rect("cascades.lambda").center());
    d.typeText("0.25");
    d.pressKey(kKeyEnter);
    EXPECT_EQ(d.s.cascades.lambda, 0.25f);
    EXPECT_FALSE(d.drawn("cascades.lambda#refused")) << "the message goes once the field is set";
}

TEST_F(EditorUiTest, TypedNumbersApplyOnEnterOrFocusLossNotPerKeystroke) {
    const float elevation = d.s.light.elevation;
    d.ctrlClick(d.rect("light.elevation").center());
    d.typeText("3");
    EXPECT_EQ(d.s.light.elevation, elevation);
    d.typeText("0");
    EXPECT_EQ(d.s.light.elevation, elevation) << "typing 30 must not apply 3 first";
    d.pressKey(kKeyEnter);
    EXPECT_EQ(d.s.light.elevation, 30.0f);
    d.ctrlClick(d.rect("light.elevation").center());
    d.typeText("12");
    d.click(d.rect("light.azimuth").center());  // the field loses the keyboard
    EXPECT_EQ(d.s.light.elevation, 12.0f);
}

// Issue 13 #7: "filter size -5 becomes 3".
// Issue 21 #11: "9 is outside 1 .. 8: not applied" outlived the values it was about.
TEST_F(EditorUiTest, ARefusalGoesWithUndoAndWithALoad) {
    d.ui().setDocument(d.s, scratch.path / "mine.json");
    st::savePresetAtomic(d.s, scratch.path / "mine.json");
    d.in.presetFiles = {scratch.path / "mine.json"};
    dragElevation();  // something to undo
    const auto refuse = [&] {
        d.ctrlClick(d.rect("cascades.count").center());
        d.typeText("9");
        d.pressKey(kKeyEnter);
        d.frame();
        return d.drawn("cascades.count#refused");
    };
    ASSERT_TRUE(refuse());
    d.pressKey(kKeyZ, true);
    d.frame();
    EXPECT_FALSE(d.drawn("cascades.count#refused")) << "undo replaced the settings";
    ASSERT_TRUE(refuse());
    EXPECT_FALSE(d.ui().dirty());
    d.click("preset:mine.json");
    d.frames(2);
    EXPECT_FALSE(d.drawn("cascades.count#refused")) << "the preset was loaded again";
}

TEST_F(EditorUiTest, ANegativeFilterSizeTypedIntoItsBoxIsRefused) {
    d.s.filter.kind = FilterKind::PcfNxN;
    d.s.filter.size = 5;
    d.frame();
    d.scroll(d.rect("light.elevation").center(), -13.0f);  // the Filter group is below the fold
    ASSERT_LT(d.rect("filter.size").max.y, 700.0f);
    d.click("filter.size");
    d.pressKey(65, true);  // Ctrl+A
    d.typeText("-5");
    EXPECT_EQ(d.s.filter.size, 5) << "nothing applies while typing";
    d.pressKey(kKeyEnter);
    EXPECT_EQ(d.s.filter.size, 5);
    EXPECT_TRUE(d.drawn("filter.size#refused"));
    d.click("filter.size");
    d.pressKey(65, true);
    d.typeText("7");
    d.pressKey(kKeyEnter);
    EXPECT_EQ(d.s.filter.size, 7);
    EXPECT_FALSE(d.drawn("filter.size#refused"));
}

// Issue 39 #10: "95 deg is outside -90 .. 90 deg" stayed on screen after edits of other fields.
TEST_F(EditorUiTest, ARefusalGoesWhenAnotherFieldTakesAValue) {
    d.ctrlClick(d.rect("light.elevation").center());  // Ctrl+click turns a slider into a text field
    d.typeText("95");
    d.pressKey(kKeyEnter);
    ASSERT_TRUE(d.drawn("light.elevation#refused"));
    d.ctrlClick(d.rect("light.azimuth").center());
    d.typeText("40");
    d.pressKey(kKeyEnter);
    EXPECT_EQ(d.s.light.azimuth, 40.0f);
    EXPECT_FALSE(d.drawn("light.elevation#refused")) << "another field took a value: the refusal is stale";
}

// Issue 39 #10: Escape left a menu open.
TEST_F(EditorUiTest, EscapeClosesAnOpenMenu) {
    d.frame();
    d.click("menu.view");
    d.frame();
    ASSERT_TRUE(d.drawn("menu.hidePanels")) << "the View menu is open";
    d.pressKey(kKeyEscape);
    d.frame();
    EXPECT_FALSE(d.drawn("menu.hidePanels"));
}

// Issue 39 #10: keys for the debug views, as View's menu sets them.
TEST_F(EditorUiTest, NumberKeysPickTheDebugViews) {
    d.frame();
    d.pressKey(50);  // 2
    EXPECT_EQ(d.s.output.view, View::Cascades);
    d.pressKey(52);  // 4
    EXPECT_EQ(d.s.output.view, View::TexelDensity);
    d.pressKey(49);  // 1
    EXPECT_EQ(d.s.output.view, View::Shaded);
}

TEST_F(EditorUiTest, FieldsTheModeDoesNotUseAreGreyed) {
    d.s.cascades.scheme = SplitScheme::Uniform;
    d.s.filter.kind = FilterKind::Pcf2x2;
    d.frame();
    EXPECT_TRUE(d.drawn("cascades.lambda#unused"));
    EXPECT_TRUE(d.drawn("filter.size#unused"));
    EXPECT_FALSE(d.drawn("light.elevation#unused"));
    d.s.cascades.scheme = SplitScheme::Practical;
    d.frame();
    EXPECT_FALSE(d.drawn("cascades.lambda#unused"));
}

// The per-cascade bias factors: "Per cascade" starts from a factor of 1 per cascade (the image as
// it was), "Same for all" empties the list; a factor of a zero bias is greyed.
TEST(EditorUiTallTest, BiasPerCascadeStartsAtOnesAndClears) {
    UiDriver d({1280.0f, 4000.0f});  // tall enough that the bias group is on screen
    FrameStats stats = fakeFrameStats();
    d.in.stats = &stats;
    d.s.cascades.count = 3;
    d.s.bias.normalOffset = 0.0f;
    d.frame();
    EXPECT_TRUE(d.drawn("bias.normalOffsetScale#unused"));
    EXPECT_FALSE(d.drawn("bias.constantScale#unused"));
    // A row per cascade, greyed while one value serves all (issue 21 #5): dragging it does nothing.
    for (const char* row : {"bias.constantScale[0]#single", "bias.constantScale[1]#single", "bias.constantScale[2]#single"})
        EXPECT_TRUE(d.drawn(row)) << row;
    EXPECT_FALSE(d.drawn("bias.constantScale[3]#single"));
    const ImVec2 row1 = d.rect("bias.constantScale[1]#single").center();
    d.drag(row1, {row1.x + 80.0f, row1.y});
    EXPECT_TRUE(d.s.bias.constantScale.empty()) << "a greyed row was edited";
    d.click("bias.constantScale#perCascade");
    EXPECT_EQ(d.s.bias.constantScale, (std::vector<float>{1.0f, 1.0f, 1.0f}));
    d.frame();
    EXPECT_FALSE(d.drawn("bias.constantScale[1]#single")) << "the rows are live now";
    const ImVec2 live1 = d.rect("bias.constantScale[1]").center();
    d.drag(live1, {live1.x + 80.0f, live1.y});
    EXPECT_EQ(d.s.bias.constantScale[0], 1.0f);
    EXPECT_GT(d.s.bias.constantScale[1], 1.0f) << "cascade 1's own factor";
    const float dragged = d.s.bias.constantScale[1];
    d.ctrlClick(d.rect("cascades.count").center());  // fewer cascades: the list follows the count
    d.typeText("2");
    d.pressKey(kKeyEnter);
    ASSERT_EQ(d.s.cascades.count, 2);
    EXPECT_EQ(d.s.bias.constantScale, (std::vector<float>{1.0f, dragged})) << "the factors kept, the third cut";
    EXPECT_TRUE(d.last.settingsValid);
    d.frame();
    d.click("bias.constantScale#sameForAll");
    EXPECT_TRUE(d.s.bias.constantScale.empty());
}

TEST_F(EditorUiTest, ManualSplitLabelsUseTheIndexValidationNames) {
    d.s.cascades.scheme = SplitScheme::Manual;
    d.s.cascades.manualSplits = {6.2f, 5.0f, 92.0f};  // [1] is not increasing
    d.frames(2);
    const auto issues = findIssues(d.s);
    ASSERT_FALSE(issues.empty());
    const std::string& path = issues.front().path;  // "cascades.manualSplits[1]"
    const std::string label = ui::elementLabel(*findField("cascades.manualSplits"), 1);
    EXPECT_EQ(path.substr(path.find('[')), label.substr(label.find('['))) << path << " vs " << label;
    EXPECT_TRUE(d.drawn("cascades.manualSplits[1]"));
}

TEST_F(EditorUiTest, SaveWritesTheEditedSettingsAndClearsTheDirtyMarker) {
    d.ui().setDocument(d.s, scratch.path / "mine.json");
    const float dragged = dragElevation();
    EXPECT_EQ(d.ui().windowTitle(), "shadowtune - mine.json *");
    d.click("presets.save");
    ASSERT_TRUE(d.ui().errors().empty()) << d.ui().errors().front();
    EXPECT_TRUE(d.last.presetsChanged);
    EXPECT_EQ(loadPreset(scratch.path / "mine.json").light.elevation, dragged);
    EXPECT_FALSE(d.ui().dirty());
    EXPECT_EQ(d.ui().windowTitle(), "shadowtune - mine.json");
}

TEST_F(EditorUiTest, CtrlSSavesAndSaveAsWritesTheTypedPath) {
    d.ui().setDocument(d.s, scratch.path / "a.json");
    dragElevation();
    d.pressKey(kKeyS, true);
    EXPECT_EQ(loadPreset(scratch.path / "a.json"), d.s);
    d.click("presets.saveAsPath");
    d.pressKey(65, true);  // Ctrl+A selects all, then type over it
    d.typeText((scratch.path / "b").string().c_str());
    d.click("presets.saveAs");
    ASSERT_TRUE(d.ui().errors().empty()) << d.ui().errors().front();
    EXPECT_EQ(d.ui().presetFile(), scratch.path / "b.json");
    EXPECT_EQ(loadPreset(scratch.path / "b.json"), d.s);
}

TEST_F(EditorUiTest, AnInvalidPresetShowsItsErrorsInsteadOfThrowing) {
    const auto bad = scratch.write("bad.json", R"({"version": 1, "cascades": {"count": 12}})");
    d.in.presetFiles = {bad};
    d.frame();
    const Settings before = d.s;
    EXPECT_NO_THROW(d.click("preset:bad.json"));
    EXPECT_EQ(d.s, before);
    ASSERT_EQ(d.ui().errors().size(), 1u);
    EXPECT_NE(d.ui().errors().front().find("cascades.count: must be in 1..8, got 12"), std::string::npos)
        << d.ui().errors().front();
    EXPECT_FALSE(d.last.presetLoaded);
}

TEST_F(EditorUiTest, LoadingOverUnsavedChangesAsksFirst) {
    Settings other;
    other.cascades.lambda = 0.9f;
    savePresetAtomic(other, scratch.path / "other.json");
    d.in.presetFiles = {scratch.path / "other.json"};
    dragElevation();
    const Settings edited = d.s;
    d.click("preset:other.json");
    EXPECT_EQ(d.s, edited) << "nothing is discarded before the user confirms";
    ASSERT_TRUE(d.drawn("confirm.discard"));
    d.click("confirm.cancel");
    EXPECT_EQ(d.s, edited);
    d.frame();
    EXPECT_FALSE(d.drawn("confirm.discard"));
    d.click("preset:other.json");
    d.click("confirm.discard");
    EXPECT_EQ(d.s, other);
    EXPECT_TRUE(d.last.presetLoaded);
    EXPECT_EQ(d.ui().presetFile(), scratch.path / "other.json");
    EXPECT_FALSE(d.ui().dirty());
}

TEST_F(EditorUiTest, QuitWithNothingUnsavedIsImmediate) {
    d.ui().requestQuit();
    d.frame();
    EXPECT_TRUE(d.last.quit);
}

TEST_F(EditorUiTest, QuitWithUnsavedChangesAsksFirst) {
    dragElevation();
    d.ui().requestQuit();
    d.frame();
    EXPECT_FALSE(d.last.quit);
    ASSERT_TRUE(d.drawn("confirm.discard"));
    d.click("confirm.discard");
    EXPECT_TRUE(d.last.quit);
}

TEST_F(EditorUiTest, CrossFieldProblemsAreReportedNotThrown) {
    d.s.camera.nearPlane = 50.0f;
    d.s.camera.farPlane = 10.0f;
    EXPECT_NO_THROW(d.frames(2));
    EXPECT_FALSE(d.last.settingsValid);
    d.s.camera.farPlane = 100.0f;
    d.frame();
    EXPECT_TRUE(d.last.settingsValid);
}

TEST_F(EditorUiTest, ClickingAShadowTileOpensTheZoomWindow) {
    d.in.shadowLayers = {fakeTexture(11), fakeTexture(12), fakeTexture(13), fakeTexture(14)};
    d.in.shadowMapSizes = {1024, 1024, 1024, 1024};
    d.frame();
    EXPECT_TRUE(d.drawn("shadow.tile3"));
    EXPECT_FALSE(d.drawn("shadow.zoom"));
    d.click("shadow.tile2");
    EXPECT_TRUE(d.drawn("shadow.zoom"));
    d.in.shadowLayers.resize(2);  // cascade count went down: the zoom closes instead of reading past the end
    d.frame();
    EXPECT_FALSE(d.drawn("shadow.zoom"));
}

TEST_F(EditorUiTest, SideViewReportsItsSizeAndOrbitDrags) {
    d.in.sideView = fakeTexture(7);
    d.frame();
    const auto r = d.rect("sideView");
    EXPECT_GT(d.last.sideViewSize.x, 100.0f);
    d.mouse(r.center(), false);
    d.frame();
    d.mouse(r.center(), true);
    d.frame();
    d.mouse({r.center().x + 15.0f, r.center().y}, true);
    d.frame();
    EXPECT_EQ(d.last.sideViewOrbit.x, 15.0f);
    d.mouse(r.center(), false);
    d.frame();
}

TEST_F(EditorUiTest, AnimatedSunTurnsTheAzimuthAtItsRate) {
    const float before = d.s.light.azimuth;
    d.click("sun.animate");
    const float afterClick = d.s.light.azimuth;
    EXPECT_EQ(afterClick, before);  // the toggle is UI state; turning starts with the next frame
    d.frames(60);  // one second at 10 deg/s
    EXPECT_NEAR(d.s.light.azimuth - afterClick, 10.0f, 0.01f);
    EXPECT_EQ(d.last.change, ChangeClass::Uniform);
}

TEST_F(EditorUiTest, ViewShortcutsBecomeRequestsAndF1TogglesHelp) {
    EXPECT_FALSE(d.drawn("help"));
    d.pressKey(kKeyF1);
    d.frame();
    EXPECT_TRUE(d.drawn("help"));
    d.pressKey(kKeyF1);
    EXPECT_FALSE(d.drawn("help"));
    ImGui::GetIO().KeysDown[kKeyTab] = true;
    d.frame();
    EXPECT_TRUE(d.last.swapSideView);
    ImGui::GetIO().KeysDown[kKeyTab] = false;
    ImGui::GetIO().KeysDown[70] = true;  // F
    d.frame();
    EXPECT_TRUE(d.last.frameScene);
    ImGui::GetIO().KeysDown[70] = false;
    d.frame();
}

namespace {

ui::AccuracyView doneAccuracy() {
    ui::AccuracyView a;
    a.state = ui::AccuracyView::State::Done;
    a.seconds = 1.25;
    a.width = 1280;
    a.height = 720;
    a.all = {800000, 120, 3, 200, 1, 0.0042};
    a.cascades = {{300000, 100, 3, 150, 0, 0.005}, {500000, 20, 0, 50, 1, 0.0035}};
    return a;
}

}  // namespace

TEST_F(EditorUiTest, AccuracyPanelShowsFiguresOnlyWhenDone) {
    d.in.accuracy.state = ui::AccuracyView::State::Settling;
    d.frame();
    EXPECT_TRUE(d.drawn("accuracy.state"));
    EXPECT_FALSE(d.drawn("accuracy.figures"));
    EXPECT_TRUE(d.last.accuracyWanted);  // open by default: the app computes
    EXPECT_FALSE(d.last.errorOverlay);   // ... but paints nothing over the scene until asked

    d.in.accuracy.state = ui::AccuracyView::State::Computing;
    d.in.accuracy.progress = 0.4f;
    d.in.accuracy.phase = "casting rays";
    d.frame();
    EXPECT_TRUE(d.drawn("accuracy.state"));
    EXPECT_FALSE(d.drawn("accuracy.figures"));

    d.in.accuracy = doneAccuracy();
    d.frame();
    EXPECT_TRUE(d.drawn("accuracy.figures"));
    EXPECT_TRUE(d.drawn("accuracy.cascades"));

    d.in.accuracy = {};
    d.in.accuracy.state = ui::AccuracyView::State::Failed;
    d.in.accuracy.error = "Embree could not create a device";
    d.frame();
    EXPECT_FALSE(d.drawn("accuracy.figures"));
}

// Issue 39 #3: the overlay was on by default, its magenta and cyan read as part of the picture.
// Off until the Accuracy panel's toggle, whose label says what the colours mean; on, then off again.
TEST_F(EditorUiTest, ErrorOverlayIsOffUntilTheAccuracyPanelsToggle) {
    d.in.accuracy = doneAccuracy();
    d.frames(2);
    ASSERT_TRUE(d.drawn("accuracy.overlay"));
    EXPECT_FALSE(d.last.errorOverlay) << "the overlay is on by default";
    d.click("accuracy.overlay");
    EXPECT_TRUE(d.last.errorOverlay);
    EXPECT_TRUE(d.last.accuracyWanted);
    d.click("accuracy.overlay");
    EXPECT_FALSE(d.last.errorOverlay);
    EXPECT_TRUE(d.last.accuracyWanted);  // the figures are still wanted

    // The toggle and its tooltip name the colours; the panel's key repeats them beside it.
    EXPECT_NE(std::string_view(ui::kErrorOverlayLabel).find("errors"), std::string_view::npos);
    for (const char* word : {"Magenta: false shadow", "Cyan: false light", "off by default"})
        EXPECT_NE(std::string_view(ui::kErrorOverlayTooltip).find(word), std::string_view::npos) << word;
}

// `editor --error-overlay` starts with it on (the smoke test's screenshot of the overlay).
TEST_F(EditorUiTest, SetErrorOverlayTurnsTheToggleOn) {
    d.ui().setErrorOverlay(true);
    d.in.accuracy = doneAccuracy();
    d.frame();
    EXPECT_TRUE(d.last.errorOverlay);
    d.click("accuracy.overlay");
    EXPECT_FALSE(d.last.errorOverlay);
}

// Issue 39 #10: Help (F1) > Memory lists where the memory goes; opened at 1000x700 the window
// stays above the bottom edge (an auto-sized window grew past it) and its table scrolls.
TEST(HelpMemoryTest, MemoryTableOpensAndTheHelpWindowStaysOnScreen) {
    UiDriver d({1000.0f, 700.0f});
    for (int i = 0; i < 14; ++i)
        d.in.memory.lines.push_back({"Accuracy and probe: object " + std::to_string(i),
                                     "1 to 3 vec4 a pixel kept, 4 a pixel of samples", std::size_t(i + 1) << 20});
    d.in.memory.residentBytes = std::size_t(600) << 20;
    d.frame();
    d.pressKey(kKeyF1);
    d.frames(3);
    ASSERT_TRUE(d.drawn("help.memoryHeader"));
    EXPECT_FALSE(d.drawn("help.memory")) << "closed until asked: the keys come first";
    d.click("help.memoryHeader");
    d.frames(3);
    EXPECT_TRUE(d.drawn("help.memory"));
    EXPECT_LE(d.rect("window.Help").max.y, 700.0f) << "the Help window runs past the bottom edge";
    EXPECT_LE(d.rect("window.Help").max.x, 1000.0f) << "the Help window runs past the right edge";
}
