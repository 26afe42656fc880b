// EditorModel without a window or a GL context (issue 21 #1): what the panels' requests and the
// camera gestures do to the document, the valid settings, A, the history and the messages.
#include "app/editor/editor_model.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <glm/geometric.hpp>

namespace st::app {
namespace {

ModelOptions yardOptions() {
    ModelOptions opt;
    opt.preset = std::filesystem::path(ST_PRESET_DIR) / "default.json";  // builtin:yard
    opt.presetDir = ST_PRESET_DIR;
    opt.executable = "/bin/false";  // no sweep is started here
    return opt;
}

// A frame's requests with nothing asked: the settings valid, no change.
ui::UiRequests quietFrame() {
    ui::UiRequests r;
    r.sceneSize = {640.0f, 360.0f};
    return r;
}

TEST(EditorModelTest, AnInvalidEditKeepsTheValidSettingsAndSaysWhyUntilAValidChange) {
    EditorModel model(yardOptions());
    const int count = model.valid().cascades.count;
    ASSERT_GE(count, 2);
    model.edit().cascades.count = 12;  // past the cascades' limit
    ui::UiRequests r = quietFrame();
    r.change = ChangeClass::Reallocate;
    r.settingsValid = false;
    model.apply(r);
    EXPECT_EQ(model.valid().cascades.count, count);  // what is rendered stays
    EXPECT_NE(model.message().find("not applied"), std::string::npos) << model.message();
    EXPECT_NE(model.message().find("cascades.count"), std::string::npos) << model.message();
    ui::UiRequests still = quietFrame();  // the next frames change nothing: the message stays
    still.settingsValid = false;
    model.apply(still);
    EXPECT_NE(model.message().find("cascades.count"), std::string::npos) << model.message();
    EXPECT_EQ(model.valid().cascades.count, count);
    model.edit().cascades.count = count;  // fixed, and the sun turned in the same edit
    model.edit().light.azimuth += 10.0f;
    r.settingsValid = true;
    model.apply(r);
    EXPECT_EQ(model.valid().light.azimuth, model.settings().light.azimuth);
    EXPECT_EQ(model.message(), "");
}

TEST(EditorModelTest, SetAsAShowsTheSplitUntilTheViewsAreSwappedOrAIsCleared) {
    EditorModel model(yardOptions());
    Settings a = model.valid();
    a.filter.kind = FilterKind::Pcf2x2;
    a.cascades.count = 2;
    ui::UiRequests r = quietFrame();
    r.abSettings = &a;
    r.abSplit = true;
    r.abDivider = 0.25f;
    model.apply(r);
    ASSERT_TRUE(model.a().has_value());
    EXPECT_EQ(model.a()->cascades.count, 2);
    EXPECT_TRUE(model.splitShown());
    EXPECT_FLOAT_EQ(model.divider(), 0.25f);
    r.swapSideView = true;  // the side camera fills the window: no split over it
    model.apply(r);
    EXPECT_TRUE(model.swapped());
    EXPECT_FALSE(model.splitShown());
    model.apply(r);  // swapped back
    EXPECT_FALSE(model.swapped());
    EXPECT_TRUE(model.splitShown());
    r = quietFrame();  // A cleared
    model.apply(r);
    EXPECT_FALSE(model.a().has_value());
    EXPECT_FALSE(model.splitShown());
}

// ImGui's null backend, so EditorUi::draw runs (its Ctrl+Z is the history's undo).
class NullImGui {
public:
    NullImGui() {
        context_ = ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.DisplaySize = {1280.0f, 720.0f};
        io.DeltaTime = 1.0f / 60.0f;
        io.KeyMap[ImGuiKey_Z] = 90;  // GLFW_KEY_Z, as imgui_impl_glfw maps it
        unsigned char* pixels = nullptr;
        int w = 0, h = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    }
    ~NullImGui() { ImGui::DestroyContext(context_); }
    void frame(EditorModel& model) {
        ImGui::NewFrame();
        const ui::UiRequests r = model.drawPanels({});
        ImGui::Render();
        model.apply(r);
    }
    void ctrlZ(EditorModel& model) {
        ImGuiIO& io = ImGui::GetIO();
        io.KeyCtrl = true;
        io.KeysDown[90] = true;
        frame(model);
        io.KeysDown[90] = false;
        io.KeyCtrl = false;
        frame(model);
    }

private:
    ImGuiContext* context_ = nullptr;
};

TEST(EditorModelTest, FrameSceneIsOneUndoStepThatCtrlZTakesBack) {
    NullImGui imgui;
    EditorModel model(yardOptions());
    imgui.frame(model);
    const CameraSettings before = model.valid().camera;
    ui::UiRequests r = quietFrame();
    r.frameScene = true;
    model.apply(r);
    EXPECT_NE(model.valid().camera.position, before.position);
    EXPECT_EQ(model.valid().camera.nearPlane, before.nearPlane);  // near and far are tuning settings
    EXPECT_EQ(model.ui().undoSteps(), 1u);
    imgui.ctrlZ(model);
    EXPECT_EQ(model.valid().camera.position, before.position);
    EXPECT_EQ(model.ui().undoSteps(), 0u);
}

TEST(EditorModelTest, AFlyDragAndAnOrbitDragAreOneUndoStepEachAndTheOrbitKeepsThePivotsDistance) {
    EditorModel model(yardOptions());
    CameraInput look;
    look.overScene = true;
    look.fly.look = true;
    look.fly.dt = 1.0f / 60.0f;
    look.mouseDelta = look.fly.mouseDelta = {12.0f, 3.0f};
    for (int i = 0; i < 3; ++i) model.applyCamera(look);
    EXPECT_EQ(model.ui().undoSteps(), 0u);  // still held
    model.applyCamera(CameraInput{.overScene = true});
    EXPECT_EQ(model.ui().undoSteps(), 1u);

    const glm::vec3 pivot = model.settings().camera.target;
    const float distance = glm::length(model.settings().camera.position - pivot);
    CameraInput orbit{.overScene = true, .mouseDelta = {40.0f, 0.0f}, .leftDown = true, .altClick = true, .pivot = pivot};
    model.applyCamera(orbit);
    EXPECT_TRUE(model.orbiting());
    orbit.altClick = false;
    model.applyCamera(orbit);
    orbit.leftDown = false;  // released: the frame's movement still belongs to the drag
    model.applyCamera(orbit);
    EXPECT_FALSE(model.orbiting());
    EXPECT_NEAR(glm::length(model.settings().camera.position - pivot), distance, 1e-3f * distance);
    model.applyCamera(CameraInput{.overScene = true});
    EXPECT_EQ(model.ui().undoSteps(), 2u);
}

// Every camera move stops the motion preview; one that is off must keep its generation, or the
// viewport forgets the previous frame each time and a moving camera never renders at the
// interactive scale (issue 39 #1: --orbit on truck-town rendered at 100 %, 1.4 fps).
TEST(EditorModelTest, AMovingCameraWithNoPreviewKeepsThePreviewsGeneration) {
    EditorModel model(yardOptions());
    const auto generation = model.preview().generation();
    for (int i = 0; i < 3; ++i) model.applyCamera(CameraInput{.scriptedOrbitDeg = 2.0f});
    EXPECT_NE(model.valid().camera, EditorModel(yardOptions()).valid().camera) << "the camera moved";
    EXPECT_EQ(model.preview().generation(), generation);
}

TEST(EditorModelTest, MessagesGoWithTheChangeThatMadeThemStale) {
    EditorModel model(yardOptions());
    model.setRenderMessage("far plane before near plane");
    EXPECT_EQ(model.message(), "far plane before near plane");
    model.setRenderMessage("");  // the next render worked
    EXPECT_EQ(model.message(), "");

    const std::string loaded = model.valid().scene;
    const int generation = model.sceneGeneration();
    model.edit().scene = "builtin:no-such-scene";
    model.apply(quietFrame());
    EXPECT_EQ(model.valid().scene, loaded);  // the scene that works keeps rendering
    EXPECT_EQ(model.sceneGeneration(), generation);
    EXPECT_NE(model.message().find("no-such-scene"), std::string::npos) << model.message();
    model.edit().scene = "builtin:box-over-plane";
    model.apply(quietFrame());
    EXPECT_EQ(model.valid().scene, "builtin:box-over-plane");
    EXPECT_EQ(model.sceneGeneration(), generation + 1);
    EXPECT_EQ(model.message(), "");
}

TEST(EditorModelTest, FullQualityWhileMovingIsAToggle) {
    EditorModel model(yardOptions());
    EXPECT_FALSE(model.fullQualityWhileMoving());
    ui::UiRequests r = quietFrame();
    r.motion.toggleFullQuality = true;
    model.apply(r);
    EXPECT_TRUE(model.fullQualityWhileMoving());
    EXPECT_TRUE(model.motionView().fullQuality);
    model.apply(quietFrame());  // stays until toggled again
    EXPECT_TRUE(model.fullQualityWhileMoving());
    model.apply(r);
    EXPECT_FALSE(model.fullQualityWhileMoving());
}

TEST(EditorModelTest, PreviewPathRendersThePresetsPathThenPlaysUntilTheViewMoves) {
    EditorModel model(yardOptions());
    const int frames = model.valid().path.frames;
    ASSERT_GT(frames, 1) << "default.json has a camera path";
    ui::UiRequests r = quietFrame();
    r.motion.previewStart = true;
    model.apply(r);
    const MotionPreview& p = model.preview();
    ASSERT_EQ(p.state(), MotionPreview::State::Rendering);
    EXPECT_EQ(p.frames(), frames);
    EXPECT_EQ(p.path().camera, model.valid().camera) << "the editor's camera observes the flicker";
    EXPECT_NE(model.message().find("rendering 0 of " + std::to_string(frames)), std::string::npos) << model.message();
    for (int i = 0; i + 1 < frames; ++i) model.preview().frameRendered();
    EXPECT_EQ(p.state(), MotionPreview::State::Rendering);
    EXPECT_NE(model.message().find("rendering " + std::to_string(frames - 1) + " of"), std::string::npos);
    model.preview().frameRendered();
    ASSERT_EQ(p.state(), MotionPreview::State::Playing);
    model.preview().flickerMeasured(0.0041);
    EXPECT_NE(model.message().find("playing, flicker F 0.410 %"), std::string::npos) << model.message();
    // The loop: kPlayFps frames a second, back to 0 after the last.
    EXPECT_EQ(p.frameAt(0.0), 0);
    EXPECT_EQ(p.frameAt(2.5 / MotionPreview::kPlayFps), 2);
    EXPECT_EQ(p.frameAt((frames + 1.5) / MotionPreview::kPlayFps), 1);
    ui::UiRequests overlay = quietFrame();
    overlay.motion.toggleFlickerOverlay = true;
    model.apply(overlay);
    EXPECT_TRUE(model.motionView().flickerOverlay);
    EXPECT_TRUE(model.motionView().previewOn);

    CameraInput look{.overScene = true};  // the view moves: the loop shows another, it stops
    look.fly.look = true;
    look.fly.dt = 1.0f / 60.0f;
    look.mouseDelta = look.fly.mouseDelta = {8.0f, 0.0f};
    model.applyCamera(look);
    EXPECT_EQ(p.state(), MotionPreview::State::Off);
    EXPECT_EQ(model.message().find("Preview path"), std::string::npos) << model.message();
}

TEST(EditorModelTest, WithoutAPresetPathThePreviewPlaysTheLastCameraMove) {
    EditorModel model(yardOptions());
    model.edit().path = {};
    model.apply(quietFrame());
    ui::UiRequests start = quietFrame();
    start.motion.previewStart = true;
    model.apply(start);
    EXPECT_FALSE(model.preview().active());
    EXPECT_NE(model.message().find("has not moved yet"), std::string::npos) << model.message();

    CameraInput look{.overScene = true};
    look.fly.look = true;
    look.fly.dt = 1.0f / 60.0f;
    look.mouseDelta = look.fly.mouseDelta = {6.0f, 0.0f};
    model.applyCamera(CameraInput{.overScene = true});  // still: the recorder's first pose
    for (int i = 0; i < 5; ++i) model.applyCamera(look);
    const CameraSettings end = model.settings().camera;
    model.applyCamera(CameraInput{.overScene = true});  // released
    ASSERT_EQ(model.recordedMove().poses().size(), 5u);
    EXPECT_EQ(model.recordedMove().poses().back().target, end.target);
    model.apply(start);
    ASSERT_EQ(model.preview().state(), MotionPreview::State::Rendering);
    EXPECT_EQ(model.preview().frames(), 5);
    EXPECT_EQ(model.preview().path().path.keyframes.size(), 5u);
    EXPECT_NE(model.message().find("your last camera move"), std::string::npos) << model.message();
    ui::UiRequests stop = quietFrame();
    stop.motion.previewStop = true;
    model.apply(stop);
    EXPECT_FALSE(model.preview().active());
}

TEST(CameraPathRecorderTest, ANewMoveReplacesTheLastAndALongOneIsThinned) {
    CameraPathRecorder rec;
    CameraSettings c;
    double t = 0.0;
    const double frame = 0.1;
    rec.frame(c, t, false);
    for (int i = 1; i <= 3; ++i) c.position.x = float(i), rec.frame(c, t += frame, true);
    rec.frame(c, t += frame, true);  // a frame without movement inside the drag: the same move
    c.position.x = 4.0f, rec.frame(c, t += 3.0, true);  // and a slow frame of the same drag
    ASSERT_EQ(rec.poses().size(), 4u);
    EXPECT_EQ(rec.poses().front().position.x, 1.0f);
    rec.frame(c, t += frame, false);  // released
    c.position.x = 5.0f, rec.frame(c, t += frame, false);  // a key step right after: the same move
    ASSERT_EQ(rec.poses().size(), 5u);
    t += CameraPathRecorder::kPauseSeconds;  // a pause: the next move replaces this one
    for (int i = 1; i <= 200; ++i) c.position.z = float(i), rec.frame(c, t += frame, false);
    EXPECT_LE(rec.poses().size(), CameraPathRecorder::kMaxPoses);
    EXPECT_GE(rec.poses().size(), CameraPathRecorder::kMaxPoses / 2);
    EXPECT_EQ(rec.poses().front().position.z, 1.0f) << "the new move from its start";
    for (std::size_t i = 1; i < rec.poses().size(); ++i)
        EXPECT_GT(rec.poses()[i].position.z, rec.poses()[i - 1].position.z) << "in order";
}

}  // namespace
}  // namespace st::app
