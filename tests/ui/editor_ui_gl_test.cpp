// The editor's panels rendered for real: ImGui's OpenGL3 backend into an offscreen framebuffer
// under the headless EGL context, driven by scripted mouse and keys. A slider is dragged, Save is
// pressed, the saved preset is read back, the drag is undone; screenshots of the panels are
// written to tests/artifacts/ui/ for a person to look at.
#include "renderer/image/image_io.h"
#include "renderer/render/image_texture.h"
#include "renderer/settings/settings_json.h"
#include "tests/support/gl_fixture.h"
#include "tests/ui/ui_gl_driver.h"
#include "tests/ui/ui_test_data.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace fs = std::filesystem;
using namespace st;
using namespace st::test;

namespace {

class EditorUiGLTest : public GLTest {
protected:
    void screenshot(GlUiDriver& d, const std::string& name) {
        const fs::path dir = fs::path(ST_ARTIFACT_DIR) / "ui";
        fs::create_directories(dir);
        writeImageAtomic(dir / name, d.screenshot());
    }
    // Some frames with changing timings, so the plots have something to draw.
    void warmUp(GlUiDriver& d, int frames) {
        for (int i = 0; i < frames; ++i) {
            const float wobble = std::sin(0.2f * float(i)) + 0.3f * std::sin(1.3f * float(i));
            stats = fakeFrameStats(wobble);
            d.in.cpuFrameMs = 14.0 + 2.0 * wobble;
            d.frame();
        }
    }
    void giveInputs(GlUiDriver& d) {
        d.in.stats = &stats;
        for (int layer = 0; layer < 4; ++layer) d.in.shadowLayers.push_back(d.makeTestTexture(128, layer));
        d.in.shadowMapSizes = {1024, 1024, 1024, 1024};
        d.in.sideView = d.makeTestTexture(64, 5);
        for (const auto& entry : fs::directory_iterator(ST_PRESET_DIR)) {
            const auto& path = entry.path();
            if (path.extension() == ".json") d.in.presetFiles.push_back(path);
        }
        std::sort(d.in.presetFiles.begin(), d.in.presetFiles.end());
        d.in.statusLine = "test harness: llvmpipe, no window";
    }

    FrameStats stats = fakeFrameStats();
    ScratchFolder scratch;
};

bool inside(const ui::ItemRect& r, ImVec2 display) {
    return r.min.x >= 0 && r.min.y >= 0 && r.max.x <= display.x && r.max.y <= display.y;
}

}  // namespace

TEST_F(EditorUiGLTest, DraggedSliderIsSavedUndoneAndScreenshotted) {
    GlUiDriver d;
    giveInputs(d);
    const fs::path file = scratch.path / "edited.json";
    d.ui().setDocument(d.s, file);
    warmUp(d, 90);

    const float before = d.s.light.elevation;
    const auto slider = d.rect("light.elevation");
    ASSERT_TRUE(inside(slider, ImGui::GetIO().DisplaySize));
    d.drag(slider.at(0.5f, 0.5f), slider.at(0.9f, 0.5f));
    const float dragged = d.s.light.elevation;
    EXPECT_GT(dragged, 55.0f);  // 90 % along -90..90 deg, less the grab's width
    EXPECT_LT(dragged, 85.0f);
    EXPECT_TRUE(d.ui().dirty());
    screenshot(d, "editor_dragged.png");

    d.click("presets.save");
    ASSERT_TRUE(d.ui().errors().empty()) << d.ui().errors().front();
    const Settings saved = loadPreset(file);
    EXPECT_EQ(saved.light.elevation, dragged);
    EXPECT_EQ(saved, d.s);
    EXPECT_FALSE(d.ui().dirty());

    d.pressKey(kKeyZ, /*ctrl=*/true);
    EXPECT_EQ(d.s.light.elevation, before);
    EXPECT_TRUE(d.ui().dirty());
    d.pressKey(kKeyZ, /*ctrl=*/true, /*shift=*/true);
    EXPECT_EQ(d.s.light.elevation, dragged);
    warmUp(d, 10);
    screenshot(d, "editor_panels.png");
    d.scroll(d.rect("light.elevation").center(), -12.0f);  // down to the figures and plots
    warmUp(d, 2);
    screenshot(d, "editor_figures.png");
}

TEST_F(EditorUiGLTest, InvalidPresetAndCrossFieldProblemsAreShownInRed) {
    GlUiDriver d;
    giveInputs(d);
    const auto bad = scratch.write("bad-count.json", R"({"version": 1, "cascades": {"count": 12}})");
    d.in.presetFiles.insert(d.in.presetFiles.begin(), bad);
    d.s.cascades.scheme = SplitScheme::Manual;
    d.s.cascades.shadowDistance = 0.05f;  // inside the near plane: a cross-field problem
    warmUp(d, 3);
    d.ui().setDocument(d.s, {});  // as the app would after its first frame: nothing unsaved
    EXPECT_NO_THROW(d.click("preset:bad-count.json"));
    ASSERT_FALSE(d.ui().errors().empty());
    EXPECT_FALSE(d.last.settingsValid);
    warmUp(d, 3);
    screenshot(d, "editor_problems.png");
}

TEST_F(EditorUiGLTest, ShadowTileZoomsOnClick) {
    GlUiDriver d;
    giveInputs(d);
    warmUp(d, 3);
    d.click("shadow.tile1");
    ASSERT_TRUE(d.drawn("shadow.zoom"));
    d.pressKey(kKeyF1);
    warmUp(d, 2);
    screenshot(d, "editor_zoom_help.png");
}

namespace {

// An overlay like the app's (top row first): a false-shadow red block above a false-light blue
// one, both in the scene area between the panels, transparent elsewhere.
Rgba8Image testOverlay(int width, int height) {
    Rgba8Image img{width, height, std::vector<std::uint8_t>(std::size_t(width) * std::size_t(height) * 4, 0)};
    auto block = [&](int y0, std::uint8_t r, std::uint8_t b) {
        for (int y = y0; y < y0 + 60; ++y)
            for (int x = 600; x < 760; ++x) {
                std::uint8_t* p = &img.pixels[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4];
                p[0] = r, p[1] = 20, p[2] = b, p[3] = 255;
            }
    };
    block(100, 230, 20);
    block(300, 20, 255);
    return img;
}

ui::AccuracyView doneAccuracy() {
    ui::AccuracyView a;
    a.state = ui::AccuracyView::State::Done;
    a.seconds = 1.25;
    a.timing = "read-back 0.10 s, BVH 0.05 s, rays 0.90 s, scoring 0.20 s";
    a.width = 1280;
    a.height = 720;
    a.all = {812345, 140, 3, 221, 1, 0.0042};
    a.cascades = {{200000, 90, 3, 120, 0, 0.0061}, {250000, 30, 0, 70, 1, 0.0040},
                  {220000, 15, 0, 25, 0, 0.0031}, {142345, 5, 0, 6, 0, 0.0022}};
    return a;
}

}  // namespace

TEST_F(EditorUiGLTest, AccuracyPanelAndOverlayAreDrawnUpright) {
    GlUiDriver d;
    giveInputs(d);
    ImageTexture overlay;
    const Rgba8Image picture = testOverlay(1280, 720);
    overlay.upload(picture.width, picture.height, picture.pixels);
    d.overlay = reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(overlay.id()));
    d.in.accuracy = doneAccuracy();
    warmUp(d, 3);
    ASSERT_TRUE(d.drawn("accuracy.figures"));
    EXPECT_LT(d.screenshot().pixels[(130 * 1280 + 680) * 4], 100) << "the overlay is drawn before it is asked for";
    d.click("accuracy.overlay");  // off by default (issue 39 #3): the toggle turns it on
    warmUp(d, 1);
    const Rgba8Image shot = d.screenshot();
    auto at = [&](int x, int y) { return &shot.pixels[(std::size_t(y) * 1280 + std::size_t(x)) * 4]; };
    EXPECT_GT(at(680, 130)[0], 200);  // red on top: texel row 0 is the picture's top row
    EXPECT_LT(at(680, 130)[2], 60);
    EXPECT_GT(at(680, 330)[2], 200);  // blue below
    EXPECT_LT(at(680, 330)[0], 60);
    screenshot(d, "editor_accuracy.png");

    d.click("accuracy.overlay");  // off again: the scene shows through
    warmUp(d, 1);
    EXPECT_LT(d.screenshot().pixels[(130 * 1280 + 680) * 4], 100);
}
