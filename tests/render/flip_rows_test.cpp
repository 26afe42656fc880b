// flipRows: GL's bottom-first rows to the top-first rows images and samples use.
#include "renderer/image/flip_rows.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace st {
namespace {

TEST(FlipRowsTest, ReversesRowsAndKeepsEachRowsOrder) {
    std::vector<std::uint8_t> odd = {1, 2, 3, 4, 5, 6};  // 3 rows of 2
    flipRows(std::span(odd), 2);
    EXPECT_EQ(odd, (std::vector<std::uint8_t>{5, 6, 3, 4, 1, 2}));
    std::vector<int> even = {1, 2, 3, 4, 5, 6, 7, 8};  // 4 rows of 2
    flipRows(std::span(even), 2);
    EXPECT_EQ(even, (std::vector<int>{7, 8, 5, 6, 3, 4, 1, 2}));
}

TEST(FlipRowsTest, TwiceIsIdentityAndOneRowIsUnchanged) {
    std::vector<int> v = {1, 2, 3, 4, 5, 6};
    const std::vector<int> original = v;
    flipRows(std::span(v), 3);
    EXPECT_NE(v, original);
    flipRows(std::span(v), 3);
    EXPECT_EQ(v, original);
    flipRows(std::span(v), 6);
    EXPECT_EQ(v, original);
    flipRows(std::span(v), 0);  // no rows: nothing to do
    EXPECT_EQ(v, original);
}

}  // namespace
}  // namespace st
