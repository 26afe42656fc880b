#include "tune/tune_explain.h"

#include "metrics/figure_table.h"
#include "renderer/settings/cascade_factors.h"
#include "renderer/settings/field_table.h"
#include "renderer/settings/kind_descriptors.h"
#include "renderer/settings/settings_json.h"
#include "sweep/sweep_results.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace st::tune {
namespace {
using Json = nlohmann::ordered_json;

// A number as a person writes it: 25.6, 68, 0.0025 (not 25.615204 or 68.0).
std::string numberText(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", std::abs(v) >= 10.0 ? std::round(v * 10.0) / 10.0 : v);
    return text;
}

std::string valueText(const nlohmann::json& v, std::string_view unit) {
    std::string t;
    if (v.is_string()) t = v.get<std::string>();
    else if (v.is_number_float()) t = numberText(v.get<double>());
    else if (v.is_array() && !v.empty() && std::all_of(v.begin(), v.end(), [](const nlohmann::json& x) { return x.is_number(); }))
        for (const nlohmann::json& x : v) t += (t.empty() ? "" : ", ") + numberText(x.get<double>());
    else t = v.dump();
    if (!unit.empty() && (v.is_number() || v.is_array()) && !v.empty()) t += " " + std::string(unit);
    return t;
}

// Settings with x's change (to: with the fields it needs, first) or without it. With fields, each
// is set as it is, as the editor applies a line (ui withAssignments): withFieldJson turns the
// manual scheme back to a computed one while the splits do not match the count.
Settings withChange(Settings s, const Explained& x, bool to) {
    if (!to || x.with.empty()) return withFieldJson(std::move(s), x.change.path, to ? x.change.to : x.change.from);
    const auto set = [&s](const std::string& path, const nlohmann::json& value) {
        const FieldInfo& f = *findField(path);
        f.set(s, readFieldValue(f, value, path));
        keepCascadeListsValid(s, path);
    };
    for (const auto& [path, value] : x.with) set(path, value);
    set(x.change.path, x.change.to);
    return s;
}

// "-0.33 pp misclassified": the error difference in the figure's display unit.
std::string errorDelta(const metrics::FigureRow& row, double delta) {
    const metrics::UnitInfo& u = metrics::unitInfo(row.unit);
    char text[64];
    std::snprintf(text, sizeof text, "%+.3g%s%s", delta * u.scale, u.deltaSymbol[0] ? " " : "", u.deltaSymbol);
    return text;
}

std::string costDelta(double from, double to) {
    char text[48];
    std::snprintf(text, sizeof text, "%+.0f %% cost", from > 0.0 ? (to / from - 1.0) * 100.0 : 0.0);
    return text;
}

std::string judged(const Evaluation& e, const metrics::FigureRow& row, const Evaluation& base, bool reversed) {
    if (!e.valid) return "not valid alone (" + e.problem + ")";
    const double dErr = reversed ? base.error - e.error : e.error - base.error;
    const double from = reversed ? e.costMs : base.costMs, to = reversed ? base.costMs : e.costMs;
    std::string out = errorDelta(row, dErr) + " " + row.label + ", " + costDelta(from, to);
    if (!e.constraintsMet) out += " (" + e.violated + ")";
    return out;
}
}  // namespace

Explanation explain(const Settings& input, const Evaluation& inputEval, const Settings& tuned,
                    const Evaluation& tunedEval, const std::string& objectiveChoice, const Evaluator& evaluate) {
    const metrics::FigureRow& row = sweep::errorFigure(objectiveChoice);
    Explanation out{row.label, inputEval, tunedEval, {}};
    const std::vector<Change> changes = changesBetween(input, tuned);
    const auto changed = [&](const std::string& path) {
        return std::find_if(changes.begin(), changes.end(), [&](const Change& c) { return c.path == path; });
    };
    // Manual splits mean nothing without the manual scheme, and the scheme nothing without the
    // splits: one line, "Manual splits [] -> 21.4, 51.3 m (with the manual scheme)", measured with
    // both (and the tuned count, when the input's has another number of splits).
    const bool coupled = tuned.cascades.scheme == SplitScheme::Manual && changed("cascades.scheme") != changes.end() &&
                         changed("cascades.manualSplits") != changes.end();
    for (const Change& c : changes) {
        // A field the tuned preset does not read (λ under manual splits) bought nothing there;
        // undoing it would change another field (a λ move computes the splits again).
        if (!fieldApplies(tuned, c.path)) continue;
        if (coupled && c.path == "cascades.scheme") continue;
        const FieldInfo* f = findField(c.path);
        Explained x{c, std::string(f->label) + (f->unit.empty() ? "" : " (" + std::string(f->unit) + ")"), {}, {}, "", {}};
        std::string also;
        if (coupled && c.path == "cascades.manualSplits") {
            if (input.cascades.count != tuned.cascades.count) {
                x.with.emplace_back("cascades.count", tuned.cascades.count);
                also = std::to_string(tuned.cascades.count) + " cascades and ";
            }
            x.with.emplace_back("cascades.scheme", "manual");
            also = " (with " + also + "the manual scheme)";
        }
        // Undoing the splits alone leaves the tuned count's splits computed again: the scheme goes back.
        const Settings without =
            coupled && c.path == "cascades.manualSplits" ? withFieldJson(tuned, "cascades.scheme", changed("cascades.scheme")->from)
                                                         : withChange(tuned, x, false);
        const Settings alone = withChange(input, x, true);
        x.alone = alone == input ? inputEval : evaluate(alone);
        x.without = without == tuned ? tunedEval : evaluate(without);
        x.line = std::string(f->label) + " " + valueText(c.from, unitIn(*f, input)) + " -> " + valueText(c.to, unitIn(*f, tuned)) + also +
                 ": alone " + judged(x.alone, row, inputEval, false) + "; in the tuned preset " +
                 judged(x.without, row, tunedEval, true);
        out.changes.push_back(std::move(x));
    }
    return out;
}

Json toJson(const Explanation& e) {
    auto eval = [](const Evaluation& v) {
        return Json{{"valid", v.valid}, {"error", v.error}, {"costMs", v.costMs}, {"mapBytes", v.mapBytes},
                    {"constraintsMet", v.constraintsMet}, {"violated", v.violated}};
    };
    Json changes = Json::array();
    for (const Explained& x : e.changes) {
        Json with = Json::object();
        for (const auto& [path, value] : x.with) with[path] = value;
        changes.push_back({{"field", x.change.path}, {"label", x.label}, {"from", x.change.from}, {"to", x.change.to},
                           {"with", with}, {"alone", eval(x.alone)}, {"withoutIt", eval(x.without)}, {"text", x.line}});
    }
    return {{"objective", e.objective}, {"input", eval(e.input)}, {"tuned", eval(e.tuned)}, {"changes", changes}};
}

std::string toMarkdown(const Explanation& e, const std::string& title) {
    std::string md = "# " + title + "\n\nObjective: " + e.objective + ". Each change from the input preset, measured "
                     "alone (the input with only that change) and in the tuned preset (the tuned preset without it: "
                     "what it buys there). Costs are modelled (the cost profile), errors averaged over the tuned views.\n\n";
    for (const Explained& x : e.changes) md += "- " + x.line + "\n";
    if (e.changes.empty()) md += "- No change: the input preset is already the best found within the budget.\n";
    return md;
}

}  // namespace st::tune
