#include "tune/tune_explain.h"

#include "metrics/figure_table.h"
#include "renderer/csm/cascade_plan.h"
#include "renderer/settings/cascade_factors.h"
#include "renderer/settings/field_table.h"
#include "renderer/settings/kind_descriptors.h"
#include "renderer/settings/settings_json.h"
#include "sweep/sweep_results.h"

#include <algorithm>
#include <cctype>
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

// An error as the figure shows it: "0.27" or "1.2 %".
std::string errorValue(const metrics::FigureRow& row, double v) {
    const metrics::UnitInfo& u = metrics::unitInfo(row.unit);
    char text[48];
    std::snprintf(text, sizeof text, "%#.3g%s%s", v * u.scale, u.symbol[0] ? " " : "", u.symbol);
    return text;
}

// "cuts the error by 66 %", "raises the error by 12 %", "leaves the error as it was": the change
// in percent of the error it starts from, as an artist reads a gain.
std::string errorChange(double from, double to) {
    if (from <= 0.0 || std::abs(to - from) <= 0.005 * from) return "leaves the error as it was";
    char text[64];
    const double pct = 100.0 * (to - from) / from;
    std::snprintf(text, sizeof text, "%s the error by %.0f %%", pct < 0.0 ? "cuts" : "raises", std::abs(pct));
    return text;
}

std::string costChange(double from, double to) {
    if (from <= 0.0 || std::abs(to - from) <= 0.005 * from) return "at the same cost";
    char text[48];
    const double pct = 100.0 * (to - from) / from;
    std::snprintf(text, sizeof text, "at %.0f %% %s cost", std::abs(pct), pct < 0.0 ? "less" : "more");
    return text;
}

// "acne 92.942 % > 52.366 %; flicker F ..." (tune_eval.cpp) as a sentence: "acne rises to
// 92.942 % from the input's 52.366 %; ...".
std::string worseSentence(const std::string& violated) {
    std::string out, rest = violated;
    while (!rest.empty()) {
        const auto end = rest.find("; ");
        std::string part = rest.substr(0, end);
        rest = end == std::string::npos ? "" : rest.substr(end + 2);
        const auto gt = part.find(" > ");
        if (gt != std::string::npos) {
            const auto name = part.rfind(' ', part.rfind(' ', gt - 1) - 1);  // "acne 92.942 %": before the value
            const std::string now = part.substr(name + 1, gt - name - 1), was = part.substr(gt + 3);
            if (now == was) continue;  // a rise below the figure's shown precision says nothing
            part = part.substr(0, name) + " rises to " + now + " from the input's " + was;
        }
        out += (out.empty() ? "" : "; ") + part;
    }
    return out;
}

// What the change does alone (from the input) or in the tuned preset (the tuned preset without
// it, reversed: what it is worth there).
std::string judged(const Evaluation& e, const metrics::FigureRow& row, const Evaluation& base, bool reversed) {
    if (!e.valid) return "not valid (" + e.problem + ")";
    const double from = reversed ? e.error : base.error, to = reversed ? base.error : e.error;
    const double costFrom = reversed ? e.costMs : base.costMs, costTo = reversed ? base.costMs : e.costMs;
    return errorChange(from, to) + " (" + row.label + " " + errorValue(row, from) + " -> " + errorValue(row, to) + ") " +
           costChange(costFrom, costTo);
}

// The splits a computed scheme gives, where the field itself is empty: "25.6, 54.8, 112.7 m (computed)".
std::string splitsText(const Settings& s, const nlohmann::json& v, std::string_view unit) {
    if (!v.is_array() || !v.empty()) return valueText(v, unit);
    const std::vector<float> splits = csm::planSplits(s, std::nullopt);
    nlohmann::json inner = nlohmann::json::array();
    for (std::size_t i = 1; i + 1 < splits.size(); ++i) inner.push_back(double(splits[i]));
    return inner.empty() ? "none" : valueText(inner, unit) + " (computed)";
}
// The artifact figures an artist sees: wrong shadow, wrong light, and the soft truth's classes.
constexpr const char* kExplainedArtifactKeys[] = {"accuracy.falseShadow", "soft.acne", "accuracy.falseLight", "soft.lightBleeding",
                                         "soft.peterPanning", "soft.missingCaster", "flicker.flipRate"};

// "False shadow rises from 0.071 % to 0.207 % of sun-facing pixels": each artifact figure the tuned
// preset has more of than the input (by more than a tenth and 0.01 points), as a sentence.
std::vector<std::string> worseFigures(const Evaluation& input, const Evaluation& tuned) {
    std::vector<std::string> out;
    for (const char* key : kExplainedArtifactKeys) {
        const auto a = input.figures.find(key), b = tuned.figures.find(key);
        if (a == input.figures.end() || b == tuned.figures.end() || !a->is_number() || !b->is_number()) continue;
        const double from = a->get<double>(), to = b->get<double>();
        if (to <= from * 1.1 || to - from <= 1e-4) continue;
        const metrics::FigureRow* row = metrics::findFigure(key);
        std::string label = row ? std::string(row->label) : std::string(key);
        if (!label.empty()) label[0] = char(std::toupper(static_cast<unsigned char>(label[0])));
        char text[160];
        std::snprintf(text, sizeof text, "%s rises from %.3g %% to %.3g %% of sun-facing pixels.", label.c_str(), 100.0 * from,
                      100.0 * to);
        out.emplace_back(text);
    }
    return out;
}

}  // namespace

Explanation explain(const Settings& input, const Evaluation& inputEval, const Settings& tuned,
                    const Evaluation& tunedEval, const std::string& objectiveChoice, const Evaluator& evaluate) {
    const metrics::FigureRow& row = sweep::errorFigure(objectiveChoice);
    Explanation out{row.label, inputEval, tunedEval, {}, worseFigures(inputEval, tunedEval)};
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
        const std::string fromText = splitsText(input, c.from, unitIn(*f, input)), toText = splitsText(tuned, c.to, unitIn(*f, tuned));
        // A move below what the line can show (an engine's projection rounding its knob: slope bias
        // 1.0000005 -> 1.0000008 texels) is no change to an artist.
        if (fromText == toText) continue;
        // Undoing the splits alone leaves the tuned count's splits computed again: the scheme goes back.
        const Settings without =
            coupled && c.path == "cascades.manualSplits" ? withFieldJson(tuned, "cascades.scheme", changed("cascades.scheme")->from)
                                                         : withChange(tuned, x, false);
        const Settings alone = withChange(input, x, true);
        x.alone = alone == input ? inputEval : evaluate(alone);
        x.without = without == tuned ? tunedEval : evaluate(without);
        x.line = std::string(f->label) + " " + fromText + " -> " + toText + also + ": alone it " + judged(x.alone, row, inputEval, false) +
                 "; in the tuned preset it " + judged(x.without, row, tunedEval, true);
        // An artifact class that gets worse with the change, said as a sentence, and the line marked.
        if (x.alone.valid && !x.alone.constraintsMet && !x.alone.violated.empty())
            if (const std::string w = worseSentence(x.alone.violated); !w.empty()) x.worse = "Alone, " + w + ".";
        if (!x.worse.empty()) x.line = "(!) " + x.line + ". " + x.worse;
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
                           {"with", with}, {"alone", eval(x.alone)}, {"withoutIt", eval(x.without)}, {"text", x.line},
                           {"worse", x.worse}});
    }
    return {{"objective", e.objective}, {"input", eval(e.input)}, {"tuned", eval(e.tuned)}, {"worse", e.worse}, {"changes", changes}};
}

std::string toMarkdown(const Explanation& e, const std::string& title) {
    std::string md = "# " + title + "\n\nObjective: " + e.objective + ". Each change from the input preset, measured "
                     "alone (the input with only that change) and in the tuned preset (against the tuned preset without it: "
                     "what it is worth there), in percent of the error it starts from. Costs are modelled (the cost "
                     "profile), errors averaged over the tuned views. (!) marks a change that makes an artifact worse.\n\n";
    for (const std::string& w : e.worse) md += "**Worse than the input:** " + w + "\n\n";
    for (const Explained& x : e.changes) md += "- " + x.line + "\n";
    if (e.changes.empty()) md += "- No change: the input preset is already the best found within the budget.\n";
    return md;
}

}  // namespace st::tune
