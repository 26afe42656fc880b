#pragma once
// The status bar's figures as text, pure so tests can check them against their own arithmetic.
#include "ui/history.h"

#include <string>

namespace st::ui {

// "12.5 fps (80.0 ms)": frames over the time they took, the plot's window (about 4 s at 60 Hz);
// "-- fps" before the first frame.
std::string frameRateText(const History& cpuFrameMs);

}  // namespace st::ui
