#pragma once
// Where each panel goes. Debian's ImGui 1.86 is built without docking, so the side columns are
// computed from the display size every frame: Settings on the left; Presets, Shadow maps and the
// Side view stacked on the right; the scene in the middle with the split bar and the Accuracy
// panel under it; a status bar along the bottom. The scene gets exactly the space the panels
// leave (UiRequests::scenePos/sceneSize), so no panel covers it at any window size. Column
// widths and the Accuracy panel's height follow the user's resizing and are kept in
// LayoutPrefs, which the app stores in its own file (not the preset).
#include <imgui.h>

namespace st::ui {

struct UiFrame;

enum class Panel { Settings, Presets, ShadowMaps, SideView, Accuracy, SplitBar, Status, ShadowZoom, Help, Confirm };

struct Rect {
    ImVec2 min{0.0f, 0.0f};
    ImVec2 max{0.0f, 0.0f};
    float width() const { return max.x - min.x; }
    float height() const { return max.y - min.y; }
    bool empty() const { return width() <= 0.0f || height() <= 0.0f; }
    // Shared area, not a shared edge: docked neighbours touch.
    bool overlaps(const Rect& o) const {
        return !empty() && !o.empty() && min.x < o.max.x && o.min.x < max.x && min.y < o.max.y && o.min.y < max.y;
    }
    bool contains(ImVec2 p) const { return p.x >= min.x && p.x < max.x && p.y >= min.y && p.y < max.y; }
};

// What the user chose and the app keeps across runs.
struct LayoutPrefs {
    float leftWidth = 430.0f;     // Settings column
    float rightWidth = 330.0f;    // Presets / Shadow maps / Side view column
    float bottomHeight = 220.0f;  // Accuracy panel under the scene
    bool panelsHidden = false;    // H or View > Hide panels: the scene fills the window
    bool operator==(const LayoutPrefs&) const = default;
};

// Which optional panels are open; a closed one gives its space to its neighbours.
struct PanelsShown {
    bool shadowMaps = true;
    bool sideView = true;
    bool accuracy = true;
};

struct Layout {
    Rect scene;  // the scene viewport
    Rect settings, presets, shadowMaps, sideView, splitBar, accuracy, status;
    const Rect& of(Panel panel) const;
};

struct LayoutMetrics {
    float menuBar = 19.0f;   // height of the main menu bar
    float statusBar = 23.0f;
    float splitBar = 52.0f;
    float scale = 1.0f;      // the UI scale (font size / 13 px): minimum column sizes grow with it
};

// The UI scale for a window `height` pixels tall: 1 up to 1440, 1.5 up to 2000, then 2 (4K), so
// text stays as large on the screen as at 1080p; SHADOWTUNE_UI_SCALE (1 .. 3) overrides it.
float uiScaleFor(int height, const char* override);

// The default column sizes at `scale` (the saved ones are the user's, in pixels, and stay).
LayoutPrefs scaledDefaults(float scale);

// Pure: the rectangles for a display at `origin` of `size`. Panels that are hidden or closed get
// empty rectangles; the scene never overlaps a non-empty one.
Layout computeLayout(ImVec2 origin, ImVec2 size, const LayoutMetrics& m, const LayoutPrefs& prefs, PanelsShown shown);

// The metrics of the current ImGui style and font.
LayoutMetrics currentLayoutMetrics();

// Begin for a docked panel: places it at f.state.layout's rectangle, takes back a column width
// or height the user dragged into f.state.prefs, and records the window's rectangle as
// "window.<panel name>". Call ImGui::End() after it whatever it returns.
bool beginDockedPanel(UiFrame& f, Panel panel, const char* name, bool* open, ImGuiWindowFlags flags = 0);

// For the floating windows (zoom, help, confirmation): where they first appear, centred.
void placeNextWindow(Panel panel);

// The Tune and Sweep windows, each time they open: over the right column (Presets, Shadow maps,
// Side view), at least `width` wide and growing left from the window's edge, the column's height,
// so the scene and an A/B split's halves stay in view (they opened over the scene, issue 39 #8).
void placeOverRightColumn(const UiFrame& f, float width);

}  // namespace st::ui
