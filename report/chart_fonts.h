#pragma once
// The font families of every text drawn into an image (charts, the front table, label strips),
// named exactly. The generic aliases ("sans", "monospace") resolve to whatever fontconfig prefers
// among the installed fonts: installing fonts-noto-mono (imagemagick brings it) turned the front
// table's "monospace" into Noto Sans Mono and changed the charts (issue 20). DejaVu comes from
// fonts-dejavu-core, which scripts/setup.sh installs and the .deb depends on.
#include <string>
#include <vector>

namespace st::report {

inline constexpr const char* kSansFamily = "DejaVu Sans";
inline constexpr const char* kSerifFamily = "DejaVu Serif";
inline constexpr const char* kMonoFamily = "DejaVu Sans Mono";
inline constexpr const char* kFontPackage = "fonts-dejavu-core";

// Every family above, sans first.
std::vector<std::string> chartFontFamilies();

// The family fontconfig picks for a text asked in `family` (regular weight), as a renderer
// using fontconfig (Pango, cairo) gets it: `family` itself when it is installed, else the
// fallback; "" when fontconfig cannot load its configuration.
std::string matchedFamily(const std::string& family);

// A warning naming `family`, the package to install and the family used instead, or "" when
// `family` is installed.
std::string missingFontWarning(const std::string& family);

// Makes PLplot's cairo driver name kSansFamily, kSerifFamily and kMonoFamily instead of its
// generic aliases (it reads them from PLPLOT_FREETYPE_*_FAMILY at plinit). Sets the environment
// once per process: call it before threads start where possible (main does); later calls do
// nothing.
void nameChartFonts();

// Prints missingFontWarning() of each family to stderr, once per process. Called before the
// first chart or label strip is drawn.
void warnAboutMissingChartFonts();

}  // namespace st::report
