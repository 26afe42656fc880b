#include "report/chart_fonts.h"

#include <fontconfig/fontconfig.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <utility>

namespace st::report {
namespace {

template <class T, void (*Free)(T*)>
struct Freer {
    void operator()(T* p) const { Free(p); }
};
using Config = std::unique_ptr<FcConfig, Freer<FcConfig, FcConfigDestroy>>;
using Pattern = std::unique_ptr<FcPattern, Freer<FcPattern, FcPatternDestroy>>;

const FcChar8* fc(const std::string& s) { return reinterpret_cast<const FcChar8*>(s.c_str()); }

// The match's family names (a font may carry several, e.g. "DejaVu Sans" and "DejaVu Sans Light").
std::vector<std::string> familiesOf(const FcPattern* match) {
    std::vector<std::string> out;
    FcChar8* name = nullptr;
    for (int i = 0; FcPatternGetString(match, FC_FAMILY, i, &name) == FcResultMatch; ++i)
        out.emplace_back(reinterpret_cast<const char*>(name));
    return out;
}

// The families of the font fontconfig matches for `family`. A configuration of its own, destroyed
// here: the process-wide one belongs to Pango and cairo (and FcFini in label_strip.cpp).
std::vector<std::string> matchedFamilies(const std::string& family) {
    const Config config{FcInitLoadConfigAndFonts()};
    const Pattern pattern{FcPatternCreate()};
    if (!config || !pattern || !FcPatternAddString(pattern.get(), FC_FAMILY, fc(family))) return {};
    FcConfigSubstitute(config.get(), pattern.get(), FcMatchPattern);
    FcDefaultSubstitute(pattern.get());
    FcResult result = FcResultNoMatch;
    const Pattern match{FcFontMatch(config.get(), pattern.get(), &result)};
    return match ? familiesOf(match.get()) : std::vector<std::string>{};
}

}  // namespace

std::vector<std::string> chartFontFamilies() { return {kSansFamily, kSerifFamily, kMonoFamily}; }

std::string matchedFamily(const std::string& family) {
    const std::vector<std::string> names = matchedFamilies(family);
    for (const std::string& name : names)
        if (name == family) return name;
    return names.empty() ? "" : names.front();
}

std::string missingFontWarning(const std::string& family) {
    const std::string used = matchedFamily(family);
    if (used == family) return "";
    return "warning: font \"" + family + "\" is not installed (Debian: apt-get install " + kFontPackage +
           "); charts and labels are drawn in \"" + (used.empty() ? "no font fontconfig found" : used) +
           "\" instead and differ from other machines'";
}

void nameChartFonts() {
    static std::once_flag once;
    std::call_once(once, [] {
        // Script and symbol text are not used; they get the sans family rather than the
        // driver's "sans,serif" list.
        for (const auto& [variable, family] : {std::pair{"PLPLOT_FREETYPE_SANS_FAMILY", kSansFamily},
                                               std::pair{"PLPLOT_FREETYPE_SERIF_FAMILY", kSerifFamily},
                                               std::pair{"PLPLOT_FREETYPE_MONO_FAMILY", kMonoFamily},
                                               std::pair{"PLPLOT_FREETYPE_SCRIPT_FAMILY", kSansFamily},
                                               std::pair{"PLPLOT_FREETYPE_SYMBOL_FAMILY", kSansFamily}})
            ::setenv(variable, family, 1);
    });
}

void warnAboutMissingChartFonts() {
    static std::once_flag once;
    std::call_once(once, [] {
        for (const std::string& family : chartFontFamilies())
            if (const std::string warning = missingFontWarning(family); !warning.empty())
                std::fprintf(stderr, "%s\n", warning.c_str());
    });
}

}  // namespace st::report
