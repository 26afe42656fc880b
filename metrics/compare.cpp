#include "metrics/compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace st::metrics {
namespace {
using OJson = nlohmann::ordered_json;

// {"accuracy": {"misclassified": ...}, ...} from the figures' dotted keys.
template <class Value>
OJson nested(const std::vector<CompareFigure>& figures, Value value) {
    OJson j = OJson::object();
    for (const CompareFigure& f : figures) {
        j[OJson::json_pointer(jsonPointer(f.key))] = figureJson(f.unit, value(f));
    }
    return j;
}

OJson diffJson(const ShadowDiff& d) {
    return OJson{{"scoredPixels", d.scored()}, {"onlyA", d.onlyA}, {"onlyB", d.onlyB}, {"both", d.both},
                 {"neither", d.neither},      {"unscoredPixels", d.unscored},
                 {"disagreeShare", d.share(d.onlyA + d.onlyB)}};
}

std::string printf1(const char* format, double v) {
    char text[64];
    std::snprintf(text, sizeof text, format, v);
    return text;
}

std::string pad(const std::string& s, std::size_t width, bool right) {
    if (s.size() >= width) return s;
    const std::string fill(width - s.size(), ' ');
    return right ? fill + s : s + fill;
}

// Display width: the table's only multibyte characters are "−" and "±" (2 and 3 UTF-8 bytes).
std::size_t columns(const std::string& s) {
    return std::size_t(std::count_if(s.begin(), s.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}

std::string padColumns(const std::string& s, std::size_t width, bool right) {
    return pad(s, width + (s.size() - columns(s)), right);
}

std::string row(std::size_t labelWidth, const std::string& label, const std::string& a, const std::string& b,
                const std::string& delta) {
    return padColumns(label, labelWidth, false) + padColumns(a, 14, true) + padColumns(b, 14, true) +
           padColumns(delta, 14, true) + "\n";
}

std::string diffLine(const ShadowDiff& d) {
    const auto pct = [&](std::size_t n) { return printf1("%.3f %%", 100.0 * d.share(n)); };
    return "unfiltered shadow test differs on " + pct(d.onlyA + d.onlyB) + " of " + std::to_string(d.scored()) +
           " scored pixels (only A shadows " + pct(d.onlyA) + ", only B shadows " + pct(d.onlyB) + ")\n";
}

}  // namespace

std::vector<CompareFigure> compareFigures(const PresetMeasurement& a, const PresetMeasurement& b,
                                          const FigureTable& table) {
    std::vector<CompareFigure> figures;
    for (const FigureRow* r : figuresShown(InCompare, table))
        figures.push_back({r->key, r->label, r->unit, r->read(a), r->read(b)});
    return figures;
}

ShadowDiff shadowDiff(const MeasureSamples& a, const MeasureSamples& b) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("shadow diff: the two measurements differ in size");
    ShadowDiff d{a.width, a.height, std::vector<DiffClass>(a.size(), DiffClass::Unscored)};
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (!a.receiver(i) || !b.receiver(i)) {
            ++d.unscored;
            continue;
        }
        const bool shadowA = a.shadow[i].x < 0.5f, shadowB = b.shadow[i].x < 0.5f;
        const DiffClass c = shadowA == shadowB ? (shadowA ? DiffClass::Both : DiffClass::Neither)
                                               : (shadowA ? DiffClass::OnlyA : DiffClass::OnlyB);
        d.classes[i] = c;
        ++(c == DiffClass::Both ? d.both : c == DiffClass::Neither ? d.neither : c == DiffClass::OnlyA ? d.onlyA : d.onlyB);
    }
    return d;
}

OJson compareJson(const CompareNames& names, const std::vector<CompareFigure>& figures, const PresetMeasurement& a,
                  const std::optional<ShadowDiff>& diff) {
    OJson j{{"view", {{"from", names.sharedView ? "a" : "each"},
                      {"scene", a.settings.scene},
                      {"width", a.samples.width},
                      {"height", a.samples.height}}}};
    j["a"] = {{"preset", names.a}, {"file", names.fileA}};
    j["a"].update(nested(figures, [](const CompareFigure& f) { return f.a; }));
    j["b"] = {{"preset", names.b}, {"file", names.fileB}};
    j["b"].update(nested(figures, [](const CompareFigure& f) { return f.b; }));
    j["delta"] = nested(figures, [](const CompareFigure& f) { return f.delta(); });
    j["shadowDiff"] = diff ? diffJson(*diff) : OJson(nullptr);
    return j;
}

std::string compareTable(const CompareNames& names, const std::vector<CompareFigure>& figures,
                         const std::optional<ShadowDiff>& diff) {
    std::string t = "A = " + names.a + ", B = " + names.b +
                    (names.sharedView ? " (B's cascades, filter and bias on A's scene, camera and light)\n"
                                      : " (each with its own scene, camera and light)\n");
    std::size_t width = 20;  // the longest label and a space
    for (const CompareFigure& f : figures) width = std::max(width, columns(f.label) + 1);
    t += row(width, "figure", "A", "B", "B − A");
    for (const CompareFigure& f : figures)
        t += row(width, f.label, formatValue(f.unit, f.a), formatValue(f.unit, f.b), formatDelta(f.unit, f.delta()));
    if (diff) t += diffLine(*diff);
    return t;
}

}  // namespace st::metrics
