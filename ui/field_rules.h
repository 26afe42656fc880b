#pragma once
// Pure helpers behind the settings widgets (no ImGui): how a field's range, step and flags turn
// into a widget choice, a printf format, a clamped value; and the figures shown beside knobs.
#include "renderer/settings/field_table.h"
#include "renderer/settings/settings.h"

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace st::ui {

// Slider when the range holds at most this many steps; a drag box otherwise (bias, distances).
inline constexpr double kMaxSliderSteps = 1000.0;

double clampToField(const FieldInfo& field, double value);  // into [min, max]

// An Int edit made legal: clamped, moved to the next odd value away from `previous` for odd
// fields (so +/- steps by 2), rounded to the nearest power of two for powerOfTwo fields.
int legalInt(const FieldInfo& field, int value, int previous);

bool prefersSlider(const FieldInfo& field);  // Float/Int with a short range (see kMaxSliderSteps)
int decimalsForStep(double step);            // 0.01 -> 2, 0.5 -> 1, 1 -> 0

// printf format for a Float widget: "%.2f m"; '%' in a unit is escaped.
std::string floatFormat(const FieldInfo& field);
std::string intFormat(const FieldInfo& field);  // "%d px"

// floatFormat with enough decimals to show `value` to two significant digits (at most 6), so a
// near plane of 0.0001 m does not show as "0.00 m" (issue 13 #7).
std::string floatFormatFor(const FieldInfo& field, double value);

// Why a typed value cannot be taken as it is ("300 deg is outside -90 .. 90 deg"), or "".
// Typed values are refused, never clamped; drags stay in range by themselves.
std::string typedValueProblem(const FieldInfo& field, double value);

// Why `field` does nothing with the rest of `s` as it is ("Used with cascades.scheme practical
// only (now uniform)."), or "" when it applies: st::notApplicableReason of the kinds' descriptors
// (renderer/settings/kind_descriptors.h). The widget is greyed with this as its tooltip.
std::string notApplicableReason(const FieldInfo& field, const Settings& s);

// The label of element i of a list field, "Manual splits [1]": the index validation messages
// name ("cascades.manualSplits[1]: ..."), so a message and its widget read the same (issue 13 #7).
std::string elementLabel(const FieldInfo& field, std::size_t i);

std::vector<int> powerOfTwoChoices(const FieldInfo& field);  // 256, 512, ... 8192 for mapSize

std::string formatBytes(std::size_t bytes);  // "16.0 MiB", "512 KiB", "12 B"
std::string formatLength(double metres);      // "3.2 mm", "4.50 cm", "12.3 m", "1.20 km"

// cascades.manualSplits resized to cascades.count - 1, keeping the values it has. New entries
// come from `currentSplits` (the renderer's count + 1 split depths) when the list was empty and
// the counts match, otherwise they are spaced evenly between the last split and the end
// (shadow distance, or the far plane), so switching to "manual" starts from something valid.
std::vector<float> fitManualSplits(const Settings& s, std::span<const float> currentSplits);

// Sun azimuth advanced by `deltaDeg`, wrapped into [0, 360) so it stays in the field's range.
float advanceAzimuth(float azimuthDeg, float deltaDeg);

}  // namespace st::ui
