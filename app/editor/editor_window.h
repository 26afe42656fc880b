#pragma once
// The editor's GLFW window with a GL 4.5 core context and Dear ImGui's GLFW + OpenGL3 backends.
// Decision: the ImGui OpenGL3 backend keeps its own loader (Debian's libimgui.a is built with
// it); the rest of shadowtune uses libepoxy. Both resolve the same driver entry points.
// Window size and the ImGui layout (imgui.ini) persist in $XDG_CONFIG_HOME/shadowtune
// (default ~/.config/shadowtune). The window fits the primary monitor's work area: the first
// launch fills it, a size kept from a larger screen shrinks to it.
#include "app/editor/key_queue.h"
#include "app/editor/mouse_queue.h"

#include <filesystem>
#include <string>

struct GLFWwindow;

namespace st::app {

class EditorWindow {
public:
    // Throws std::runtime_error when there is no display or no GL 4.5 core context.
    EditorWindow(const std::string& title, bool debugContext);
    ~EditorWindow();
    EditorWindow(const EditorWindow&) = delete;
    EditorWindow& operator=(const EditorWindow&) = delete;

    GLFWwindow* handle() const { return window_; }
    bool shouldClose() const;  // the close button, or SIGINT/SIGTERM (Ctrl+C in the terminal)
    // shouldClose as it stood just before this frame polled its events. A Ctrl+C is a signal, not an
    // X event: one that comes while a frame renders is seen by the shell before that frame has
    // polled the clicks sent just before it (still in the X socket), and a Save clicked before
    // Ctrl+C was then asked about as unsaved. Acting on the close only as of the last poll
    // puts every event sent before it into the queues first (issue 21, EditorXdotoolTest).
    bool closeAskedAtPoll() const { return closeAsked_; }
    void cancelClose();  // the close button was handled: keep running until the panels agree
    void beginFrame();  // poll events, start an ImGui frame
    // Waits until an event comes (input, resize, expose, focus) or `timeoutSeconds` pass; a
    // negative timeout waits for an event only, waking twice a second to see Ctrl+C
    // (shouldClose), which no GLFW event reports. Draws nothing.
    void waitEvents(double timeoutSeconds);
    // Events GLFW delivered so far: the shell compares counts to see whether a frame had any.
    unsigned long eventCount() const { return events_; }
    // Key or mouse events wait in the queues for a later frame (one change per key or button a frame).
    bool inputQueued() const { return keysQueued_ || !mouse_.empty(); }
    void endFrame();    // render ImGui over the back buffer
    void swapBuffers();
    void setTitle(const std::string& title);
    const std::string& title() const { return title_; }  // "shadowtune - <preset file>[ *]"
    void framebufferSize(int& w, int& h) const;
    const std::filesystem::path& configDir() const { return configDir_; }
    float uiScale() const { return uiScale_; }  // 1, 1.5 or 2 by the window's height (ui::uiScaleFor)

private:
    static void keyCallback(GLFWwindow* window, int key, int scancode, int action, int mods);
    static void cursorPosCallback(GLFWwindow* window, double x, double y);
    static void mouseButtonCallback(GLFWwindow* window, int button, int action, int mods);
    static void countEvent(GLFWwindow* window);

    GLFWwindow* window_ = nullptr;
    KeyQueue keys_;  // fed to ImGui a change per key per frame, so no tap is lost (issue 13 #3)
    MouseQueue mouse_;  // likewise a button change per frame, at the place it happened
    std::filesystem::path configDir_;
    float uiScale_ = 1.0f;
    std::string iniPath_;  // must outlive the ImGui context (io.IniFilename points into it)
    std::string title_;
    unsigned long events_ = 0;
    bool keysQueued_ = false;
    bool closeAsked_ = false;  // shouldClose() just before beginFrame's poll
};

}  // namespace st::app
