// The families charts and label strips name resolve to themselves through fontconfig, whatever
// other fonts are installed; a missing one is warned about with the font used instead. The
// ctest entry report.fonts_elsewhere runs these and the chart golden once more with the generic
// families pointed at another font (generic_fonts_elsewhere.conf, ST_GENERIC_FONTS_MOVED=1).
#include "report/chart_fonts.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace {
using namespace st::report;

TEST(ChartFontsTest, EveryFamilyResolvesToItself) {
    ASSERT_EQ(chartFontFamilies(), (std::vector<std::string>{"DejaVu Sans", "DejaVu Serif", "DejaVu Sans Mono"}));
    for (const std::string& family : chartFontFamilies()) {
        EXPECT_EQ(matchedFamily(family), family) << "install " << kFontPackage;
        EXPECT_EQ(missingFontWarning(family), "");
    }
}

TEST(ChartFontsTest, AMissingFamilyIsWarnedAboutWithTheFontUsedInstead) {
    const std::string missing = "Shadowtune No Such Font";
    const std::string used = matchedFamily(missing);
    ASSERT_FALSE(used.empty()) << "fontconfig matched nothing at all";
    EXPECT_NE(used, missing);
    EXPECT_EQ(missingFontWarning(missing), "warning: font \"Shadowtune No Such Font\" is not installed (Debian: apt-get "
                                           "install fonts-dejavu-core); charts and labels are drawn in \"" +
                                               used + "\" instead and differ from other machines'");
}

// Under generic_fonts_elsewhere.conf the generic families are another font: what the golden
// test then proves (the chart does not change) is not proved by accident.
TEST(ChartFontsTest, TheGenericFamiliesAreElsewhereUnderTheTestConfig) {
    if (!std::getenv("ST_GENERIC_FONTS_MOVED")) GTEST_SKIP() << "only under report.fonts_elsewhere";
    EXPECT_EQ(matchedFamily("monospace"), "DejaVu Serif");
    EXPECT_EQ(matchedFamily("sans-serif"), "DejaVu Serif");
}

}  // namespace
