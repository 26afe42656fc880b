// The files a sweep folder ends with, all rewritten from the point results each time (so a
// resumed, sharded or merged sweep reports exactly what one run would).
#include "report/charts.h"
#include "report/pareto.h"
#include "renderer/image/image_io.h"
#include "renderer/settings/settings_json.h"
#include "sweep/sweep_results.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace st::sweep {
namespace fs = std::filesystem;
namespace {

std::string number(double v) {
    if (!std::isfinite(v)) return "";
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", v);
    return text;
}

std::string short3(double v) {  // table cells: three significant digits
    if (!std::isfinite(v)) return "-";
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
}

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string out = "\"";
    for (const char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

void writeCsv(const fs::path& file, const Manifest& m, const std::vector<PointResult>& results) {
    std::string text = "id,kind,label";
    for (const std::string& f : m.axisFields) text += "," + f;
    if (!results.empty())
        for (const auto& [k, v] : results.front().figures) text += "," + k;
    text += "\n";
    for (const PointResult& r : results) {
        text += r.id + "," + (r.reference ? "reference" : "grid") + "," + csvField(r.label);
        for (const std::string& v : r.axisValues) text += "," + csvField(unquoted(v));
        for (const auto& [k, v] : r.figures) text += "," + number(v);
        text += "\n";
    }
    writeTextAtomic(file, text);
}

// Scene paths in the saved presets are relative to the base preset's folder: rewrite them for
// a preset in `folder`, or keep them absolute where no relative path exists.
nlohmann::ordered_json presetIn(const fs::path& folder, const Manifest& m, nlohmann::ordered_json settings) {
    const std::string scene = settings.value("scene", "");
    if (!scene.empty() && scene.rfind("builtin:", 0) != 0 && fs::path(scene).is_relative()) {
        const fs::path abs = (m.presetDir / scene).lexically_normal();
        const fs::path rel = abs.lexically_relative(fs::absolute(folder).lexically_normal());
        settings["scene"] = rel.empty() ? abs.string() : rel.string();
    }
    return settings;
}

std::string machineLine(const Manifest& m) { return m.machine.empty() ? "" : "machine: " + m.machine; }

std::vector<bool> frontOf(const std::vector<PointResult>& results, const std::string& xKey, const std::string& yKey) {
    std::vector<std::pair<double, double>> xy;
    for (const PointResult& r : results) xy.push_back({r.figure(xKey), r.figure(yKey)});
    return report::paretoFront(xy);
}

// A column header or title word for a figure key: "GPU ms", "misclassified %".
std::string shortName(const std::string& key) {
    if (key == "gpu_ms") return "GPU ms";
    if (key == "shadow_map_mib") return "map MiB";
    if (key == "misclassified_pct") return "misclassified %";
    if (key == "flicker_F_pct") return "flicker F %";
    if (key == "filtered_error") return "filtered error";
    if (key == "soft_filtered_error") return "filtered error vs the sun's disc";
    if (key == "penumbra_width_abs_error_px") return "penumbra width error px";
    if (key.ends_with("_pct")) {
        std::string name = key.substr(0, key.size() - 4);
        for (char& c : name)
            if (c == '_') c = ' ';
        return name + " %";
    }
    return key;
}

report::ScatterChart scatter(const Manifest& m, const std::vector<PointResult>& results, const std::string& xKey,
                             const std::string& xLabel, const std::string& yKey, const std::string& yLabel) {
    const std::string xShort = shortName(xKey), yShort = shortName(yKey);
    report::ScatterChart c;
    c.title = "sweep " + m.sweep + ", " + std::to_string(m.width) + "x" + std::to_string(m.height) + ": " + yShort +
              " against " + xShort;
    c.subtitle = std::to_string(results.size()) + " points, scene " + fs::path(m.scene).filename().string() + "; " +
                 machineLine(m);
    c.xLabel = xLabel;
    c.yLabel = yLabel;
    c.logY = true;
    const std::vector<bool> front = frontOf(results, xKey, yKey);
    c.tableHeader = {"front point", xShort, yShort};
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < results.size(); ++i) {
        const PointResult& r = results[i];
        c.points.push_back({r.figure(xKey), r.figure(yKey), r.label, front[i], r.reference});
        if (front[i]) order.push_back(i);
    }
    std::sort(order.begin(), order.end(), [&](auto a, auto b) { return results[a].figure(xKey) < results[b].figure(xKey); });
    for (const std::size_t i : order)
        c.tableRows.push_back({results[i].label, short3(results[i].figure(xKey)), short3(results[i].figure(yKey))});
    return c;
}

// Grid points whose axes other than `axis` hold the manifest's base values, in value order.
std::vector<const PointResult*> alongAxis(const Manifest& m, const std::vector<PointResult>& results, std::size_t axis) {
    std::vector<const PointResult*> line(m.axisValues[axis].size(), nullptr);
    for (const PointResult& r : results) {
        if (r.reference || r.axisValues.size() != m.axisFields.size()) continue;
        bool onLine = true;
        for (std::size_t b = 0; b < m.axisFields.size(); ++b) onLine = onLine && (b == axis || r.axisValues[b] == m.baseValues[b]);
        if (!onLine) continue;
        const auto& values = m.axisValues[axis];
        const auto at = std::find(values.begin(), values.end(), r.axisValues[axis]);
        if (at != values.end()) line[std::size_t(at - values.begin())] = &r;
    }
    return line;
}

void writeAxisCharts(const fs::path& dir, const Manifest& m, const std::vector<PointResult>& results,
                     const std::string& yKey, const std::string& yLabel) {
    const std::vector<std::pair<std::string, std::string>> figures = {{yKey, yLabel}, {"gpu_ms", "GPU time, shadow + main (ms)"},
                                                                      {"shadow_map_mib", "shadow-map memory (MiB)"}};
    for (std::size_t a = 0; a < m.axisFields.size(); ++a) {
        const auto line = alongAxis(m, results, a);
        std::string held;
        for (std::size_t b = 0; b < m.axisFields.size(); ++b)
            if (b != a) held += (held.empty() ? "others at " : ", ") + m.axisFields[b] + "=" + unquoted(m.baseValues[b]);
        for (const auto& [key, label] : figures) {
            report::LineChart c;
            c.title = m.sweep + ": " + key + " against " + m.axisFields[a];
            c.subtitle = held.empty() ? machineLine(m) : held + "; " + machineLine(m);
            c.xLabel = m.axisFields[a];
            c.yLabel = label;
            for (const std::string& v : m.axisValues[a]) c.xTickLabels.push_back(unquoted(v));
            report::Series s{key, {}, {}};
            for (std::size_t i = 0; i < line.size(); ++i)
                if (line[i] && std::isfinite(line[i]->figure(key))) s.x.push_back(double(i)), s.y.push_back(line[i]->figure(key));
            c.series.push_back(s);
            const std::string stem = "axis-" + m.axisFields[a] + "-" + key;
            report::writeLineChart(c, dir / (stem + ".png"), fs::path());
        }
    }
}

std::string yLabelOf(const std::string& key) {
    if (key == "filtered_error") return "filtered error (mean |filtered - truth|)";
    if (key == "flicker_F_pct") return "flicker F (% of sun-facing pixels per frame)";
    if (key == "soft_filtered_error") return "filtered error against the sun's disc (mean |filtered - soft truth|)";
    if (key == "penumbra_width_abs_error_px") return "penumbra width error (|filtered - true| mean width, px)";
    if (key == "acne_pct" || key == "light_bleeding_pct" || key == "peter_panning_pct" || key == "missing_caster_pct")
        return shortName(key) + " of sun-facing pixels (filtered, against the sun's disc)";
    return "misclassified (% of sun-facing pixels)";
}

std::vector<std::string> writeFront(const fs::path& dir, const Manifest& m, const std::vector<PointResult>& results,
                                    const std::vector<bool>& front, const std::string& yKey) {
    std::error_code ec;
    fs::create_directories(dir / "front", ec);
    if (ec) throw std::runtime_error((dir / "front").string() + ": cannot create folder: " + ec.message());
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    std::vector<std::string> ids;
    for (std::size_t i = 0; i < results.size(); ++i) {
        if (!front[i]) continue;
        const PointResult& r = results[i];
        const fs::path preset = dir / "front" / (r.id + ".json");
        Settings s = fromJson(presetIn(dir / "front", m, r.settings), preset.string());
        s.notes = "Pareto front point of sweep " + m.sweep + ": " + r.label;
        savePresetAtomic(s, preset);
        list.push_back({{"id", r.id}, {"label", r.label}, {"preset", "front/" + r.id + ".json"},
                        {"gpu_ms", r.figure("gpu_ms")}, {yKey, r.figure(yKey)}});
        ids.push_back(r.id);
    }
    writeTextAtomic(dir / "front.json", list.dump(2) + "\n");
    return ids;
}

}  // namespace

std::vector<std::string> writeReport(const fs::path& dir, const Manifest& m, const std::vector<PointResult>& results,
                                     const ReportOptions& opt) {
    const std::string yKey = errorKey(opt.error);
    const std::string yLabel = yLabelOf(yKey);
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw std::runtime_error(dir.string() + ": cannot create output folder: " + ec.message());
    writeCsv(dir / "results.csv", m, results);
    nlohmann::ordered_json all = {{"manifest", toJson(m)}, {"points", nlohmann::ordered_json::array()}};
    for (const PointResult& r : results) all["points"].push_back(toJson(r));
    writeTextAtomic(dir / "results.json", all.dump(2) + "\n");
    const std::string timeLabel = "GPU time, shadow + main (ms, median)";
    report::writeScatterChart(scatter(m, results, "gpu_ms", timeLabel, yKey, yLabel), dir / "pareto.png", dir / "pareto.svg");
    report::writeScatterChart(scatter(m, results, "shadow_map_mib", "shadow-map memory (MiB)", yKey, yLabel),
                              dir / "pareto-memory.png", dir / "pareto-memory.svg");
    writeAxisCharts(dir, m, results, yKey, yLabel);
    return writeFront(dir, m, results, frontOf(results, "gpu_ms", yKey), yKey);
}

}  // namespace st::sweep
