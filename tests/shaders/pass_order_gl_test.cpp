// Every pass sets its whole state when it starts, so the passes give the same pixels in any
// order and after any state another pass (or the UI) left behind.
#include "renderer/gpu/pass_state.h"
#include "renderer/render/measure_pass.h"
#include "renderer/render/renderer.h"
#include "renderer/render/shadow_map_view.h"
#include "renderer/settings/settings_json.h"
#include "tests/support/gl_fixture.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

using namespace st;

namespace {
class PassOrderGLTest : public test::GLTest {};

// Every piece of state a pass could inherit, set to what would break it.
void scrambleState() {
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_GREATER);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glFrontFace(GL_CW);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(4.0f, 64.0f);
    glEnable(GL_DEPTH_CLAMP);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 7, 5);
    glViewport(3, 3, 11, 13);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

struct Frame {
    std::vector<std::uint8_t> image;
    MeasureSamples samples;
};

struct Passes {
    Scene scene;
    Renderer renderer{scene};
    MeasurePass measure;
    ShadowMapView tiles;
    OffscreenTarget side;
    explicit Passes(Scene s) : scene(std::move(s)), renderer(scene) {}

    Frame frame(const Settings& s) {
        renderer.render(s);
        Frame f{renderer.readRgba8(), measure.run(renderer, s, renderer.plan().csProj * renderer.plan().vsView)};
        return f;
    }
    void others(const Settings& s) {
        side.ensure(96, 64);
        renderer.renderSideView(s, {}, side);
        tiles.update(renderer.shadowMaps(), 64);
        measure.run(renderer, s, renderer.plan().csProj * renderer.plan().vsView);
    }
};

Settings smallPreset(const char* name, View view) {
    Settings s = loadPreset(std::string(ST_PRESET_DIR) + "/" + name);
    s.output.width = 160;
    s.output.height = 90;
    s.output.view = view;
    return s;
}

void expectSame(const Frame& a, const Frame& b, const std::string& what) {
    EXPECT_TRUE(a.image == b.image) << what << ": the image changed";
    EXPECT_TRUE(a.samples.shadow == b.samples.shadow) << what << ": the measured shadow changed";
    EXPECT_TRUE(a.samples.position == b.samples.position) << what << ": the measured coverage changed";
}
}  // namespace

TEST_F(PassOrderGLTest, PassesGiveTheSamePixelsInAnyOrderAndAfterAnyState) {
    // Pancaking (depth clamp in the shadow pass) and double-sided materials exercise the state
    // that differs between passes.
    for (const char* preset : {"default.json", "soft-shadows-blog.json"}) {
        Settings s = smallPreset(preset, View::Cascades);
        Passes p(loadScene(s.scene, ST_PRESET_DIR));
        const Frame clean = p.frame(s);
        const std::vector<std::pair<std::string, std::function<void()>>> before = {
            {"side view, tiles and measure first", [&] { p.others(s); }},
            {"scrambled state", [] { scrambleState(); }},
            {"other passes, then scrambled state", [&] { p.others(s), scrambleState(); }},
        };
        for (const auto& [what, run] : before) {
            run();
            expectSame(clean, p.frame(s), std::string(preset) + ", " + what);
        }
        scrambleState();  // and left for whatever runs next: the fixture's own checks
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    }
}

TEST_F(PassOrderGLTest, SideViewIsTheSameAfterScrambledState) {
    Settings s = smallPreset("default.json", View::Side);
    Passes p(loadScene(s.scene, ST_PRESET_DIR));
    const Frame clean = p.frame(s);
    scrambleState();
    expectSame(clean, p.frame(s), "side view");
}
