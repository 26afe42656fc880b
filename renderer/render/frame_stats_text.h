#pragma once
// The shadow pass's time as the commands and the editor print it. A kept map costs nothing this
// frame, so its timer reads 0.0 ms; that is said as "kept", not shown as a time.
#include "renderer/render/frame_stats.h"

#include <cstdio>
#include <string>

namespace st {

// "shadow 12.3 ms"; "shadow kept" when every map was kept from an earlier frame; "shadow 3.1 ms
// (2 of 4 maps kept)" when some were. `decimals` of the milliseconds.
inline std::string shadowTimeText(const FrameStats& s, int decimals = 1) {
    int kept = 0;
    for (const CascadeStats& c : s.cascades) kept += c.redrawn ? 0 : 1;
    if (!s.cascades.empty() && kept == int(s.cascades.size())) return "shadow kept";
    char text[96];
    std::snprintf(text, sizeof text, "shadow %.*f ms", decimals, s.gpuShadowMs);
    std::string out = text;
    if (kept > 0) out += " (" + std::to_string(kept) + " of " + std::to_string(s.cascades.size()) + " maps kept)";
    return out;
}

}  // namespace st
