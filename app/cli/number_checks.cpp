#include "app/cli/number_checks.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace st::app {
namespace {

std::string plainNumber(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

// The option's text as a finite number, or the reason it is not one.
std::string readFinite(const std::string& text, double& value) {
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    if (text.empty() || end == text.c_str() || *end != '\0') return "'" + text + "' is not a number";
    if (!std::isfinite(value)) return "'" + text + "' is not a finite number";
    return "";
}

CLI::Validator finiteCheck(const std::string& description, double lo, bool loOpen, double hi) {
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            double v = 0.0;
            if (std::string why = readFinite(text, v); !why.empty()) return why;
            const bool low = loOpen ? !(v > lo) : !(v >= lo);
            if (low || v > hi) return text + " is outside " + description;
            return "";
        },
        description);
}

}  // namespace

CLI::Validator positiveNumber() { return finiteCheck("(0, inf): a number above 0", 0.0, true, HUGE_VAL); }

CLI::Validator nonNegativeNumber() { return finiteCheck("[0, inf): a number of at least 0", 0.0, false, HUGE_VAL); }

CLI::Validator numberIn(double lo, double hi) { return finiteCheck(plainNumber(lo) + " .. " + plainNumber(hi), lo, false, hi); }

}  // namespace st::app
