#include "ui/sweep_axes.h"

#include "renderer/settings/settings_json.h"
#include "renderer/settings/validation.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>

namespace st::ui {
namespace {

std::vector<std::string> tokens(const std::string& text) {
    std::vector<std::string> out;
    std::string cur;
    for (const char c : text + ",") {
        if (c == ',' || c == ' ' || c == '\t' || c == ';') {
            if (!cur.empty()) out.push_back(cur);
            cur.clear();
        } else {
            cur += c;
        }
    }
    return out;
}

// A token as the JSON a preset would hold: numbers and booleans as such, the rest (enum names)
// as strings, so "sphere" and "\"sphere\"" both work.
nlohmann::json tokenJson(const FieldInfo& field, const std::string& t) {
    if (field.kind == FieldKind::Float || field.kind == FieldKind::Int) {
        char* end = nullptr;
        const double v = std::strtod(t.c_str(), &end);
        if (end && *end == '\0') {
            if (field.kind == FieldKind::Int && v == std::floor(v)) return static_cast<long long>(v);
            return v;
        }
    }
    if (field.kind == FieldKind::Bool && (t == "true" || t == "false")) return t == "true";
    if (t.size() >= 2 && t.front() == '"' && t.back() == '"') return t.substr(1, t.size() - 2);
    return t;
}

std::string firstMessage(const SettingsError& e) {
    return e.messages().empty() ? std::string(e.what()) : e.messages().front();
}

}  // namespace

ParsedAxis parseAxis(const AxisEdit& edit, const std::vector<std::string>& sweepable, const std::string& label) {
    ParsedAxis out;
    const std::string at = label + " (" + edit.field + "): ";
    const FieldInfo* field = findField(edit.field);
    if (!field || std::find(sweepable.begin(), sweepable.end(), edit.field) == sweepable.end()) {
        out.errors.push_back(label + ": \"" + edit.field + "\" is not a field a sweep can vary");
        return out;
    }
    SweepAxisRequest axis{edit.field, nlohmann::json::array(), edit.range};
    if (edit.range) {
        if (field->kind != FieldKind::Float && field->kind != FieldKind::Int) {
            out.errors.push_back(at + "a range needs a number field; list its values");
            return out;
        }
        if (!(edit.step > 0.0) || !(edit.to >= edit.from)) {
            out.errors.push_back(at + "a range needs step > 0 and to >= from");
            return out;
        }
        // The sweep reader's count (sweep/sweep_spec.cpp rangeValues), so the panel's total is its total.
        const double count = std::floor((edit.to - edit.from) / edit.step + 1e-6) + 1.0;
        if (count > double(kMaxEditorSweepPoints)) {
            out.errors.push_back(at + "the range gives " + std::to_string(static_cast<long long>(count)) +
                                 " values, more than " + std::to_string(kMaxEditorSweepPoints));
            return out;
        }
        out.count = std::size_t(count);
        for (const double v : {edit.from, edit.from + (out.count - 1) * edit.step}) {
            try {
                readFieldValue(*field, field->kind == FieldKind::Int ? nlohmann::json(std::llround(v)) : nlohmann::json(v),
                               "range");
            } catch (const SettingsError& e) {
                out.errors.push_back(at + firstMessage(e));
                return out;
            }
        }
        axis.values = {{"from", edit.from}, {"to", edit.to}, {"step", edit.step}};
        out.axis = std::move(axis);
        return out;
    }
    const std::vector<std::string> list = tokens(edit.list);
    if (list.empty()) {
        out.errors.push_back(at + "give values, separated by commas");
        return out;
    }
    std::set<std::string> seen;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const nlohmann::json v = tokenJson(*field, list[i]);
        try {
            const std::string text = fieldValueToJson(*field, readFieldValue(*field, v, "value " + std::to_string(i + 1))).dump();
            if (!seen.insert(text).second) out.errors.push_back(at + "\"" + list[i] + "\" is given twice");
        } catch (const SettingsError& e) {
            out.errors.push_back(at + firstMessage(e));
        }
        axis.values.push_back(v);
    }
    out.count = list.size();
    if (out.errors.empty()) out.axis = std::move(axis);
    return out;
}

ParsedSweep parseSweep(const std::vector<AxisEdit>& axes, const std::vector<std::string>& sweepable, int width,
                       int height) {
    ParsedSweep out;
    SweepRequest request;
    request.width = width;
    request.height = height;
    std::size_t points = 1;
    for (std::size_t i = 0; i < axes.size(); ++i) {
        if (axes[i].field.empty()) continue;
        ParsedAxis a = parseAxis(axes[i], sweepable, "axis " + std::to_string(i + 1));
        out.errors.insert(out.errors.end(), a.errors.begin(), a.errors.end());
        if (!a.axis) continue;
        for (const SweepAxisRequest& other : request.axes)
            if (other.field == a.axis->field) out.errors.push_back("axis " + std::to_string(i + 1) + ": " + other.field + " is already the other axis");
        points *= a.count;
        request.axes.push_back(std::move(*a.axis));
    }
    if (request.axes.empty() && out.errors.empty()) out.errors.push_back("pick a field for at least one axis");
    if (points > kMaxEditorSweepPoints && !request.axes.empty())
        out.errors.push_back(std::to_string(points) + " points: more than the editor's " +
                             std::to_string(kMaxEditorSweepPoints) + " (run a sweep file with `shadowtune sweep`)");
    if (width < 16 || height < 16) out.errors.push_back("the sweep size must be at least 16x16");
    out.points = points;
    if (out.errors.empty()) out.request = std::move(request);
    return out;
}

}  // namespace st::ui
