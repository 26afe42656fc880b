// The shadow time as printed: a kept map is said to be kept, not shown as 0.0 ms.
#include "renderer/render/frame_stats_text.h"

#include <gtest/gtest.h>

namespace st {
namespace {

FrameStats withCascades(std::initializer_list<bool> redrawn, double shadowMs) {
    FrameStats s;
    s.gpuShadowMs = shadowMs;
    for (bool r : redrawn) s.cascades.push_back(CascadeStats{.redrawn = r});
    return s;
}

TEST(FrameStatsText, EveryMapDrawnPrintsTheTime) {
    EXPECT_EQ(shadowTimeText(withCascades({true, true}, 12.34)), "shadow 12.3 ms");
    EXPECT_EQ(shadowTimeText(withCascades({true}, 12.345), 2), "shadow 12.35 ms");
}

TEST(FrameStatsText, EveryMapKeptSaysKept) {
    EXPECT_EQ(shadowTimeText(withCascades({false, false, false}, 0.0)), "shadow kept");
}

TEST(FrameStatsText, SomeMapsKeptCountsThem) {
    EXPECT_EQ(shadowTimeText(withCascades({true, false, true, false}, 3.14)), "shadow 3.1 ms (2 of 4 maps kept)");
}

}  // namespace
}  // namespace st
