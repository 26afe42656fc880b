// History: the ring buffer the timing plots read.
#include "ui/history.h"

#include <gtest/gtest.h>

using st::ui::History;

TEST(HistoryTest, FillsThenWrapsKeepingTheNewestValues) {
    History h(3);
    EXPECT_EQ(h.size(), 0u);
    EXPECT_EQ(h.latest(), 0.0f);
    h.push(1.0f);
    h.push(2.0f);
    EXPECT_EQ(h.size(), 2u);
    EXPECT_EQ(h.offset(), 0u);
    EXPECT_EQ(h.latest(), 2.0f);
    h.push(3.0f);
    h.push(4.0f);  // overwrites 1
    EXPECT_EQ(h.size(), 3u);
    EXPECT_EQ(h.latest(), 4.0f);
    // Oldest to newest, read the way PlotLines reads a ring: data[(i + offset) % size].
    std::vector<float> ordered;
    for (std::size_t i = 0; i < h.size(); ++i) ordered.push_back(h.data()[(i + h.offset()) % h.size()]);
    EXPECT_EQ(ordered, (std::vector<float>{2.0f, 3.0f, 4.0f}));
    EXPECT_FLOAT_EQ(h.mean(), 3.0f);
    EXPECT_EQ(h.max(), 4.0f);
}

TEST(HistoryTest, ClearEmptiesIt) {
    History h(2);
    h.push(1.0f);
    h.push(2.0f);
    h.push(3.0f);
    h.clear();
    EXPECT_EQ(h.size(), 0u);
    h.push(7.0f);
    EXPECT_EQ(h.latest(), 7.0f);
}
