#pragma once
// The validation rules of Settings, written once: the JSON reader, the editor and the preset
// writer all call these. Per-field rules come from the field table (range, power of two, odd,
// non-empty); cross-field rules (near < far, split order, ...) live in validation.cpp.
#include "renderer/settings/field_table.h"
#include "renderer/settings/settings.h"

#include <functional>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace st {

struct SettingsIssue {
    std::string path;    // JSON path, with an element index where it helps: "cascades.manualSplits[2]"
    std::string reason;  // "must be in 1..8, got 12"
    std::string message() const { return path + ": " + reason; }
};

using PathSet = std::set<std::string, std::less<>>;

// The rule for one number of `field` (a Float/Int value or one Vec3/FloatList element): finite,
// within [min, max] (in float precision for float fields), a power of two or odd if flagged.
// Returns the reason it breaks the rule, or nullopt. Takes a double so the JSON reader can check
// a value before narrowing it.
std::optional<std::string> checkNumber(const FieldInfo& field, double value);

// Every rule `s` breaks: the per-field rules of each field not in `untrusted`, then each
// cross-field rule whose inputs passed their own rules and are not in `untrusted`. The JSON reader
// passes the fields it could not read, so a broken field is reported once and not again through
// the rules that depend on it.
std::vector<SettingsIssue> findIssues(const Settings& s, const PathSet& untrusted = {});

// findIssues(s) as "path: reason" messages; empty when `s` is valid.
std::vector<std::string> validate(const Settings& s);

// One sentence per cross-field rule, for the schema and docs (JSON Schema cannot express them).
std::vector<std::string_view> crossFieldRuleDescriptions();

}  // namespace st
