// The Settings panel's Engine section under ImGui's null backend (issue "Tune for your engine",
// item 5): with an engine chosen, what it has no knob for is greyed (a drag there changes nothing,
// where it does without an engine), a knob typed in the engine's own name runs through its model
// as one undo step, "Keep only what it takes" leaves nothing it lacks, Copy puts the paste-ready
// text on the clipboard, and Go asks the tune for that engine.
#include "renderer/export/engine_knobs.h"
#include "renderer/export/engine_snippets.h"
#include "tests/ui/ui_driver.h"
#include "ui/panels.h"
#include "tests/ui/ui_test_data.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace st;
using namespace st::test;

namespace {

class EngineUiTest : public ::testing::Test {
protected:
    // Tall, so the Engine section and the bias group fit without scrolling.
    EngineUiTest() : d({1280.0f, 2600.0f}) {}
    void SetUp() override {
        d.in.stats = &stats;
        d.frames(2);
    }
    // A drag across the slope-scaled bias's widget: what it did to the value.
    float dragSlope() {
        const float before = d.s.bias.slope;
        const ui::ItemRect r = d.rect("bias.slope");
        d.drag(r.at(0.5f, 0.5f), r.at(0.95f, 0.5f));
        d.frames(2);
        return d.s.bias.slope - before;
    }
    FrameStats stats = fakeFrameStats();
    UiDriver d;
};

}  // namespace

TEST_F(EngineUiTest, WhatTheEngineLacksIsGreyed) {
    EXPECT_NE(dragSlope(), 0.0f) << "without an engine the slope bias is a live setting";
    d.s.bias.slope = 1.0f;
    d.ui().setEngine(xport::Engine::ThreeJs);
    d.frames(2);
    EXPECT_EQ(dragSlope(), 0.0f) << "three.js has no slope-scaled bias: its widget is greyed";
    ASSERT_TRUE(d.drawn("engine.lacks"));
    d.click("engine.project");
    d.frames(2);
    EXPECT_TRUE(xport::knobsFor(xport::Engine::ThreeJs, d.s).lacks.empty()) << xport::knobsFor(xport::Engine::ThreeJs, d.s).lacks.front();
    EXPECT_EQ(d.s.bias.slope, 0.0f);
    EXPECT_FALSE(d.drawn("engine.lacks"));
}

TEST_F(EngineUiTest, AKnobInTheEnginesNameIsOneUndoStep) {
    d.ui().setEngine(xport::Engine::Godot);
    d.frames(2);
    const Settings before = d.s;
    d.replaceText("engine.knob.directional_shadow_mode", "1");
    EXPECT_EQ(d.s.cascades.count, 2) << "Godot's PARALLEL_2_SPLITS";
    EXPECT_EQ(xport::knobsFor(xport::Engine::Godot, d.s).knobs.at("directional_shadow_mode"), 1);
    d.replaceText("engine.knob.directional_shadow_mode", "7");
    EXPECT_EQ(d.s.cascades.count, 2) << "a knob out of range is refused, the settings kept";
    d.pressKey(kKeyZ, true);
    EXPECT_EQ(d.s.cascades, before.cascades) << "one Ctrl+Z: back to the settings before the knob";
}

TEST_F(EngineUiTest, CopyPutsThePasteReadyTextOnTheClipboardAndGoTunesForTheEngine) {
    d.ui().setEngine(xport::Engine::Babylon);
    d.frames(2);
    d.click("engine.copy.babylon.js");
    d.frames(1);
    const auto text = xport::engineSnippets(xport::Engine::Babylon, xport::knobsFor(xport::Engine::Babylon, d.s).knobs);
    ASSERT_EQ(text.size(), 1u);
    ASSERT_NE(ImGui::GetClipboardText(), nullptr);
    EXPECT_EQ(std::string(ImGui::GetClipboardText()), text.front().text);
    d.chooseMenu("menu.compare", "menu.compare.tune");
    d.click("tune.go");
    ASSERT_TRUE(d.last.tuneStart.has_value());
    EXPECT_EQ(d.last.tuneStart->engine, "babylon");
}

// Every engine with a knob table can be chosen in the editor (a table added without its line in the
// Engine choice would be reachable from the command line only).
TEST(EngineChoiceTest, OffersEveryEngineWithAKnobTable) {
    const std::vector<xport::Engine> offered = ui::engineChoices();
    for (std::size_t i = 0; i < xport::kEngineNames.size(); ++i) {
        const auto e = xport::Engine(i);
        EXPECT_EQ(std::count(offered.begin(), offered.end(), e), xport::hasKnobTable(e) ? 1 : 0) << xport::engineName(e);
    }
}
