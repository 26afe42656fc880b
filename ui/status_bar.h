#pragma once
// The status bar's figures as text, pure so tests can check them against their own arithmetic.
#include "ui/history.h"

#include <functional>
#include <string>
#include <vector>

namespace st::ui {

// "12.5 fps (80.0 ms)": from the median of the last kFpsFrames frame times, so it follows a
// change within a few frames and one slow frame does not move it (a mean over the plot's 4 s
// lagged: 57 -> 20 fps over 4 s of motion, issue 21 #3); "-- fps" before the first frame.
inline constexpr std::size_t kFpsFrames = 15;
std::string frameRateText(const History& cpuFrameMs);

// "saves render at 640 x 360 (the preset's output size)": `render` of a saved preset draws its
// output size, not the viewport's, so the framing can differ (issue 21 #9).
std::string saveSizeText(int outputWidth, int outputHeight, float sceneWidth, float sceneHeight);

// The scene image on screen: the editor redraws it only when something it shows changed, and
// at a lower resolution while the view moves (issue 13 #10), so the UI's frame rate above is not
// the scene's cost.
struct SceneRenderFigures {
    double ms = 0.0;       // wall time of the image's render (0: none yet)
    double scale = 1.0;    // of the viewport's width and height; < 1 while the view moves
    int mapSize = 0;       // the maps' size while the view moves (0: the preset's)
    bool reused = false;   // this frame showed the image of an earlier one
};

// "render 48 ms", "render 21 ms (interactive: 50 %, maps 1024, far ones staggered)",
// "image reused (rendered in 48 ms)": the scene image's figures, beside the UI's frame rate.
std::string sceneRenderText(const SceneRenderFigures& scene);

// The same, short, for a narrow window: "render 21 ms (50 %, maps 1024)", "reused (48 ms)".
std::string sceneRenderBrief(const SceneRenderFigures& scene);
// "saves at 640 x 360 (framing differs)", "saves at 640 x 360, as shown".
std::string saveSizeBrief(int outputWidth, int outputHeight, float sceneWidth, float sceneHeight);

// One piece of the status bar, in its full and its short wording.
struct StatusItem {
    std::string full, brief;
};

// What each item shows in a bar `width` wide, items `spacing` apart (`textWidth` measures a
// text): every full wording if they fit; else the last items take their short wording, one by
// one from the end, until the line fits; if even the short ones do not, the last items are
// dropped (""). At 1000x700 the full line ran 350 px past the window's edge (issue 21).
std::vector<std::string> fitStatusItems(const std::vector<StatusItem>& items, float width, float spacing,
                                        const std::function<float(const std::string&)>& textWidth);

}  // namespace st::ui
