#pragma once
// One ImGui widget per settings field, chosen from the field table row alone (kind, range, step,
// unit, flags). Every edit is clamped to the row's range and written through FieldInfo::set.
#include "renderer/settings/field_table.h"
#include "renderer/settings/settings.h"
#include "ui/item_rects.h"

#include <functional>
#include <map>
#include <string>

namespace st::ui {

// Typed numbers between frames (issue 13 #7). A number typed into a widget (Ctrl+click or
// double-click on a drag or slider, or an int box) is applied on Enter or when the widget loses
// the keyboard, not per keystroke; one outside the field's rules is refused, with the reason
// shown in red under the widget until the field is set again. Drags apply live, in range.
struct FieldEdits {
    std::map<std::string, FieldValue, std::less<>> pending;    // by path ("a.b" or "a.b[i]"): typed so far
    std::map<std::string, std::string, std::less<>> refused;   // by path: why the last typed value was not taken
};

// Draws `field`'s widget and help marker, records its rectangle under the field's path; true
// when the value changed. A kind this code does not know is shown greyed and left alone; a
// field that does not apply to `s` (notApplicableReason) is greyed with the reason as tooltip.
bool drawFieldWidget(const FieldInfo& field, Settings& s, ItemRects& rects, FieldEdits& edits);

// "(?)" after the last item; hovering shows the help, range, unit and what a change costs.
void drawHelpMarker(const FieldInfo& field);

// Writes `value` if it differs from the field's current value; true if it did.
bool storeField(const FieldInfo& field, Settings& s, const FieldValue& value);

// A power-of-two Int field as a combo of its allowed values; `note(value)` (optional) is shown
// beside each choice, e.g. the memory a map size costs. With `rects`, each open choice's
// rectangle is recorded as "<path>:<value>" (so tests can pick one).
bool editPowerOfTwo(const FieldInfo& field, Settings& s, const std::function<std::string(int)>& note,
                    ItemRects* rects = nullptr);

// A float list drawn as one drag box per element, labelled "<label> [i]" like the JSON path
// that validation messages name; rectangles are recorded as "<path>[i]". True when an element
// changed (typed elements as drawFieldWidget takes them).
bool editFloatElements(const FieldInfo& field, std::vector<float>& values, ItemRects& rects, FieldEdits& edits);

}  // namespace st::ui
