#pragma once
// Asking before an expensive map-size change (issue 11 #7); limits and costs in ui/map_cost.h.
#include "ui/ui_state.h"

namespace st::ui {

// Called after `field`'s widget changed f.s from `before`: when the change costs more than the
// limits allow, restores `before`, holds the change and opens the modal; true when it did.
bool holdExpensiveEdit(UiFrame& f, const FieldInfo& field, const Settings& before);

// The modal: Apply (one undo step) or Cancel (settings and history untouched).
void drawConfirmMapCost(UiFrame& f);

}  // namespace st::ui
