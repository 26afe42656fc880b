#include "app/editor/editor_window.h"

#include "renderer/gpu/debug_output.h"
#include "renderer/image/image_io.h"
#include "renderer/render/present.h"
#include "ui/layout.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <stdexcept>

namespace st::app {
namespace fs = std::filesystem;
namespace {
// Ctrl+C in the terminal (or SIGTERM) closes the window as its close button does: the panels ask
// about unsaved changes, and the layout and window size are saved. A second one ends the process.
std::atomic<bool> interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

extern "C" void onWindowInterrupt(int sig) {
    interrupted = true;
    std::signal(sig, SIG_DFL);
}

fs::path configDirectory() {
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg) return fs::path(xdg) / "shadowtune";
    if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".config" / "shadowtune";
    return fs::current_path() / ".shadowtune";
}

// The size window.json keeps, if it holds a usable one.
bool loadWindowSize(const fs::path& dir, int& w, int& h) {
    std::ifstream in(dir / "window.json");
    nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (!j.is_object() || j.value("width", 0) < 320 || j.value("height", 0) < 240) return false;
    w = std::min(j.value("width", w), 8192);
    h = std::min(j.value("height", h), 8192);
    return true;
}

struct WorkArea {
    int x = 0, y = 0, width = 0, height = 0;
};

// The primary monitor's work area (the screen less the panels and docks), or nothing when GLFW
// knows no monitor.
std::optional<WorkArea> primaryWorkArea() {
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    if (!monitor) return std::nullopt;
    WorkArea a;
    glfwGetMonitorWorkarea(monitor, &a.x, &a.y, &a.width, &a.height);
    if (a.width <= 0 || a.height <= 0) return std::nullopt;
    return a;
}

// The window follows the screen it opens on: the first launch takes the whole work area, and a
// size kept from a larger screen shrinks to fit this one (a 1920x1080 window.json on a 1024x600
// screen left the status bar and the right column off screen). Once the window exists, its
// frame (title bar, borders; none without a window manager) is taken off too, and the window is
// moved to the work area's corner if it would not fit where it is.
void fitWindowToScreen(GLFWwindow* window, const WorkArea& area) {
    int left = 0, top = 0, right = 0, bottom = 0;
    glfwGetWindowFrameSize(window, &left, &top, &right, &bottom);
    int w = 0, h = 0, x = 0, y = 0;
    glfwGetWindowSize(window, &w, &h);
    glfwGetWindowPos(window, &x, &y);
    const int fitW = std::max(1, std::min(w, area.width - left - right));
    const int fitH = std::max(1, std::min(h, area.height - top - bottom));
    if (fitW != w || fitH != h) glfwSetWindowSize(window, fitW, fitH);
    const bool inside = x - left >= area.x && y - top >= area.y && x + fitW + right <= area.x + area.width &&
                        y + fitH + bottom <= area.y + area.height;
    if (!inside) glfwSetWindowPos(window, area.x + left, area.y + top);
}

void saveWindowSize(const fs::path& dir, GLFWwindow* window) {
    int w = 0, h = 0;
    glfwGetWindowSize(window, &w, &h);
    std::error_code ec;
    fs::create_directories(dir, ec);
    try {
        writeTextAtomic(dir / "window.json", nlohmann::json{{"width", w}, {"height", h}}.dump() + "\n");
    } catch (const std::exception&) {
        // Not being able to remember the size is no reason to fail at exit.
    }
}
}  // namespace

EditorWindow::EditorWindow(const std::string& title, bool debugContext) : title_(title) {
    if (!glfwInit()) throw std::runtime_error("cannot open a window: GLFW could not initialise (is DISPLAY set?)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debugContext ? GLFW_TRUE : GLFW_FALSE);
    configDir_ = configDirectory();
    int w = 1280, h = 720;
    const bool saved = loadWindowSize(configDir_, w, h);
    const std::optional<WorkArea> area = primaryWorkArea();
    if (area && !saved) w = area->width, h = area->height;
    if (area) w = std::min(w, area->width), h = std::min(h, area->height);
    window_ = glfwCreateWindow(w, h, title.c_str(), nullptr, nullptr);
    if (!window_) {
        glfwTerminate();
        throw std::runtime_error("cannot open a window with an OpenGL 4.5 core context");
    }
    if (area) fitWindowToScreen(window_, *area);
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(1);
    if (debugContext) gpu::enableDebugOutput();
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    std::error_code ec;
    fs::create_directories(configDir_, ec);
    iniPath_ = (configDir_ / "imgui.ini").string();
    ImGui::GetIO().IniFilename = iniPath_.c_str();
    ImGui::StyleColorsDark();
    // A 4K window gets its text and widgets twice as large, as a 1080p one shows them (issue 39 #8).
    int shownW = 0, shownH = 0;
    glfwGetWindowSize(window_, &shownW, &shownH);
    uiScale_ = ui::uiScaleFor(shownH, std::getenv("SHADOWTUNE_UI_SCALE"));
    if (uiScale_ != 1.0f) {
        ImFontConfig font;
        font.SizePixels = 13.0f * uiScale_;
        ImGui::GetIO().Fonts->AddFontDefault(&font);
        ImGui::GetStyle().ScaleAllSizes(uiScale_);
    }
    ImGui_ImplGlfw_InitForOpenGL(window_, true);
    // Keys and mouse buttons go through our queues instead of the backend's callbacks, which
    // wrote io.KeysDown directly and latched presses only; the backend keeps the wheel, text,
    // focus and cursor-enter callbacks. Its NewFrame still writes io.MouseDown and io.MousePos
    // from the live state, which beginFrame overwrites from the queue. 1.86's backend sets no
    // cursor-position callback, so ours replaces nothing.
    glfwSetWindowUserPointer(window_, this);
    glfwSetKeyCallback(window_, keyCallback);
    glfwSetMouseButtonCallback(window_, mouseButtonCallback);
    glfwSetCursorPosCallback(window_, cursorPosCallback);
    // The backend's other callbacks, each counted as an event first (waitEvents), and the window's
    // own events: a resize or an expose must be redrawn.
    glfwSetScrollCallback(window_, [](GLFWwindow* w, double x, double y) {
        countEvent(w);
        ImGui_ImplGlfw_ScrollCallback(w, x, y);
    });
    glfwSetCharCallback(window_, [](GLFWwindow* w, unsigned int c) {
        countEvent(w);
        ImGui_ImplGlfw_CharCallback(w, c);
    });
    glfwSetWindowFocusCallback(window_, [](GLFWwindow* w, int f) {
        countEvent(w);
        ImGui_ImplGlfw_WindowFocusCallback(w, f);
    });
    glfwSetCursorEnterCallback(window_, [](GLFWwindow* w, int e) {
        countEvent(w);
        ImGui_ImplGlfw_CursorEnterCallback(w, e);
    });
    glfwSetWindowSizeCallback(window_, [](GLFWwindow* w, int, int) { countEvent(w); });
    glfwSetFramebufferSizeCallback(window_, [](GLFWwindow* w, int, int) { countEvent(w); });
    glfwSetWindowRefreshCallback(window_, [](GLFWwindow* w) { countEvent(w); });
    glfwSetWindowIconifyCallback(window_, [](GLFWwindow* w, int) { countEvent(w); });
    glfwSetWindowCloseCallback(window_, [](GLFWwindow* w) { countEvent(w); });
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window_, &x, &y);  // where a click before the first move happens
    mouse_.place(x, y);
    ImGui_ImplOpenGL3_Init("#version 450");
    interrupted = false;
    std::signal(SIGINT, onWindowInterrupt);
    std::signal(SIGTERM, onWindowInterrupt);
}

EditorWindow::~EditorWindow() {
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    saveWindowSize(configDir_, window_);
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window_);
    glfwTerminate();
}

bool EditorWindow::shouldClose() const { return glfwWindowShouldClose(window_) || interrupted; }

void EditorWindow::cancelClose() {
    glfwSetWindowShouldClose(window_, GLFW_FALSE);
    interrupted = false;
    closeAsked_ = false;
}

void EditorWindow::countEvent(GLFWwindow* window) { ++static_cast<EditorWindow*>(glfwGetWindowUserPointer(window))->events_; }

void EditorWindow::keyCallback(GLFWwindow* window, int key, int, int action, int) {
    countEvent(window);
    if (action == GLFW_REPEAT) return;  // ImGui makes its own repeats from the held key
    static_cast<EditorWindow*>(glfwGetWindowUserPointer(window))->keys_.push(key, action == GLFW_PRESS);
}

void EditorWindow::cursorPosCallback(GLFWwindow* window, double x, double y) {
    countEvent(window);
    static_cast<EditorWindow*>(glfwGetWindowUserPointer(window))->mouse_.move(x, y);
}

void EditorWindow::mouseButtonCallback(GLFWwindow* window, int button, int action, int) {
    countEvent(window);
    static_cast<EditorWindow*>(glfwGetWindowUserPointer(window))->mouse_.button(button, action == GLFW_PRESS);
}

void EditorWindow::beginFrame() {
    closeAsked_ = shouldClose();  // before the poll: whatever was sent before it comes in with the poll
    glfwPollEvents();
    ImGuiIO& io = ImGui::GetIO();
    keysQueued_ = keys_.feed(io.KeysDown);
    const Modifiers held = modifiersOf(io.KeysDown);
    io.KeyCtrl = held.ctrl, io.KeyShift = held.shift, io.KeyAlt = held.alt, io.KeySuper = held.super;
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    static_assert(IM_ARRAYSIZE(ImGuiIO::MouseDown) == MouseQueue::kButtons);
    const auto shown = mouse_.feed();
    std::copy(mouse_.down().begin(), mouse_.down().end(), io.MouseDown);
    if (shown) io.MousePos = {shown->x, shown->y};  // else the backend's: the cursor, or none when it left
    ImGui::NewFrame();
}

void EditorWindow::waitEvents(double timeoutSeconds) {
    if (timeoutSeconds >= 0.0) {
        glfwWaitEventsTimeout(timeoutSeconds);
        return;
    }
    const unsigned long before = events_;
    while (events_ == before && !shouldClose()) glfwWaitEventsTimeout(0.5);
}

void EditorWindow::endFrame() {
    ImGui::Render();
    int w = 0, h = 0;
    framebufferSize(w, h);
    // The backend sets blending and scissoring itself; the rest is the window's framebuffer.
    bindWindowForOverlay(w, h);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void EditorWindow::swapBuffers() { glfwSwapBuffers(window_); }

void EditorWindow::setTitle(const std::string& title) {
    if (title == title_) return;
    title_ = title;
    glfwSetWindowTitle(window_, title.c_str());
}

void EditorWindow::framebufferSize(int& w, int& h) const { glfwGetFramebufferSize(window_, &w, &h); }

}  // namespace st::app
