#pragma once
// One ImGui widget per settings field, chosen from the field table row alone (kind, range, step,
// unit, flags). Every edit is clamped to the row's range and written through FieldInfo::set.
#include "renderer/settings/field_table.h"
#include "renderer/settings/settings.h"
#include "ui/item_rects.h"

#include <functional>
#include <string>

namespace st::ui {

// Draws `field`'s widget and help marker, records its rectangle under the field's path; true
// when the value changed. A kind this code does not know is shown greyed and left alone.
bool drawFieldWidget(const FieldInfo& field, Settings& s, ItemRects& rects);

// "(?)" after the last item; hovering shows the help, range, unit and what a change costs.
void drawHelpMarker(const FieldInfo& field);

// Writes `value` if it differs from the field's current value; true if it did.
bool storeField(const FieldInfo& field, Settings& s, const FieldValue& value);

// A power-of-two Int field as a combo of its allowed values; `note(value)` (optional) is shown
// beside each choice, e.g. the memory a map size costs.
bool editPowerOfTwo(const FieldInfo& field, Settings& s, const std::function<std::string(int)>& note);

// A float list drawn as one drag box per element ("<label> 1", ...), each clamped to the
// field's range; rectangles are recorded as "<path>[i]". True when an element changed.
bool editFloatElements(const FieldInfo& field, std::vector<float>& values, ItemRects& rects);

}  // namespace st::ui
