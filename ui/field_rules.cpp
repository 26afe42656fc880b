#include "ui/field_rules.h"

#include "renderer/settings/kind_descriptors.h"
#include "renderer/settings/number_text.h"
#include "renderer/settings/split_range.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace st::ui {
namespace {

std::string escapedUnit(const FieldInfo& field) {
    std::string unit;
    for (const char c : field.unit) unit += (c == '%') ? std::string("%%") : std::string(1, c);
    return unit.empty() ? unit : " " + unit;
}

int nearestPowerOfTwo(int value) {
    int lower = 1;
    while (lower * 2 <= value) lower *= 2;
    return (value - lower < lower * 2 - value) ? lower : lower * 2;
}

std::string printed(const char* format, double value) {
    char text[64];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

}  // namespace

double clampToField(const FieldInfo& field, double value) {
    if (std::isnan(value)) return field.min;
    return std::clamp(value, field.min, field.max);
}

int legalInt(const FieldInfo& field, int value, int previous) {
    if (field.powerOfTwo) value = nearestPowerOfTwo(std::max(value, 1));
    if (field.odd && value % 2 == 0) value += (value >= previous) ? 1 : -1;
    int clamped = static_cast<int>(clampToField(field, value));
    if (field.odd && clamped % 2 == 0) clamped += (clamped > field.min) ? -1 : 1;
    return clamped;
}

bool prefersSlider(const FieldInfo& field) {
    if (field.step <= 0.0) return false;
    return (field.max - field.min) / field.step <= kMaxSliderSteps;
}

int decimalsForStep(double step) {
    if (step <= 0.0 || step >= 1.0) return 0;
    return std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 0, 6);
}

std::string floatFormat(const FieldInfo& field) {
    return "%." + std::to_string(decimalsForStep(field.step)) + "f" + escapedUnit(field);
}

std::string intFormat(const FieldInfo& field) { return "%d" + escapedUnit(field); }

std::string floatFormatFor(const FieldInfo& field, double value) {
    int decimals = decimalsForStep(field.step);
    const double a = std::fabs(value);
    if (a > 0.0 && a < 1.0) decimals = std::max(decimals, static_cast<int>(std::ceil(-std::log10(a) - 1e-9)) + 1);
    return "%." + std::to_string(std::min(decimals, 6)) + "f" + escapedUnit(field);
}

std::string elementLabel(const FieldInfo& field, std::size_t i) {
    return std::string(field.label) + " [" + std::to_string(i) + "]";
}

std::string typedValueProblem(const FieldInfo& field, double value) {
    const std::string unit = field.unit.empty() ? "" : " " + std::string(field.unit);
    if (std::isnan(value)) return "not a number";
    if (value < field.min || value > field.max)
        return formatNumber(value) + unit + " is outside " + formatNumber(field.min) + " .. " + formatNumber(field.max) + unit;
    const bool integral = field.kind == FieldKind::Int;
    if (integral && field.odd && static_cast<long long>(value) % 2 == 0) return formatNumber(value) + " is even; it must be odd";
    if (integral && field.powerOfTwo && (static_cast<long long>(value) & (static_cast<long long>(value) - 1)) != 0)
        return formatNumber(value) + " is not a power of two";
    return {};
}

std::string notApplicableReason(const FieldInfo& field, const Settings& s) {
    return st::notApplicableReason(s, field.path);  // the kinds' descriptors (kind_descriptors.h)
}

std::vector<int> powerOfTwoChoices(const FieldInfo& field) {
    std::vector<int> sizes;
    for (long long size = 1; size <= static_cast<long long>(field.max); size *= 2) {
        if (size >= field.min) sizes.push_back(static_cast<int>(size));
    }
    return sizes;
}

std::string formatBytes(std::size_t bytes) {
    const double value = static_cast<double>(bytes);
    if (bytes >= (std::size_t{1} << 30)) return printed("%.2f GiB", value / double(1 << 30));
    if (bytes >= (std::size_t{1} << 20)) return printed("%.1f MiB", value / double(1 << 20));
    if (bytes >= (std::size_t{1} << 10)) return printed("%.0f KiB", value / double(1 << 10));
    return printed("%.0f B", value);
}

std::string formatLength(double metres) {
    const double a = std::fabs(metres);
    if (a >= 1000.0) return printed("%.2f km", metres / 1000.0);
    if (a >= 1.0) return printed(a >= 100.0 ? "%.0f m" : "%.1f m", metres);
    if (a >= 0.01) return printed("%.2f cm", metres * 100.0);
    return printed("%.1f mm", metres * 1000.0);
}

std::vector<float> fitManualSplits(const Settings& s, std::span<const float> currentSplits) {
    const auto& c = s.cascades;
    const auto needed = static_cast<std::size_t>(std::max(c.count - 1, 0));
    std::vector<float> splits(c.manualSplits.begin(),
                              c.manualSplits.begin() + static_cast<std::ptrdiff_t>(std::min(needed, c.manualSplits.size())));
    if (splits.empty() && currentSplits.size() == needed + 2) {
        return {currentSplits.begin() + 1, currentSplits.end() - 1};
    }
    const float end = splitRangeEnd(s.camera, c);
    const float last = splits.empty() ? s.camera.nearPlane : splits.back();
    const std::size_t missing = needed - splits.size();
    for (std::size_t j = 0; j < missing; ++j) {
        splits.push_back(last + (end - last) * static_cast<float>(j + 1) / static_cast<float>(missing + 1));
    }
    return splits;
}

float advanceAzimuth(float azimuthDeg, float deltaDeg) {
    const float wrapped = std::fmod(azimuthDeg + deltaDeg, 360.0f);
    return wrapped < 0.0f ? wrapped + 360.0f : wrapped;
}

}  // namespace st::ui
