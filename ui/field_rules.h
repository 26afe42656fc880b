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
