#include "tune/tune_explain.h"

#include "metrics/figure_table.h"
#include "renderer/settings/field_table.h"
#include "renderer/settings/kind_descriptors.h"
#include "renderer/settings/settings_json.h"
#include "sweep/sweep_results.h"

#include <cmath>
#include <cstdio>

namespace st::tune {
namespace {
using Json = nlohmann::ordered_json;

std::string valueText(const nlohmann::json& v, std::string_view unit) {
    std::string t = v.is_string() ? v.get<std::string>() : v.dump();
    if (!unit.empty() && v.is_number()) t += " " + std::string(unit);
    return t;
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
    for (const Change& c : changesBetween(input, tuned)) {
        // A field the tuned preset does not read (λ under manual splits) bought nothing there;
        // undoing it would change another field (a λ move computes the splits again).
        if (!fieldApplies(tuned, c.path)) continue;
        const FieldInfo* f = findField(c.path);
        Explained x{c, std::string(f->label) + (f->unit.empty() ? "" : " (" + std::string(f->unit) + ")"), {}, {}, ""};
        const Settings alone = withFieldJson(input, c.path, c.to);
        const Settings without = withFieldJson(tuned, c.path, c.from);
        x.alone = alone == input ? inputEval : evaluate(alone);
        x.without = without == tuned ? tunedEval : evaluate(without);
        x.line = std::string(f->label) + " " + valueText(c.from, f->unit) + " -> " + valueText(c.to, f->unit) +
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
    for (const Explained& x : e.changes)
        changes.push_back({{"field", x.change.path}, {"label", x.label}, {"from", x.change.from}, {"to", x.change.to},
                           {"alone", eval(x.alone)}, {"withoutIt", eval(x.without)}, {"text", x.line}});
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
