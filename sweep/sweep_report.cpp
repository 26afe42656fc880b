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

// A raw figure in the CSV: counts and bytes whole, others to six significant digits.
std::string number(metrics::FigureUnit unit, double v) {
    if (std::isfinite(v) && (unit == metrics::FigureUnit::Count || unit == metrics::FigureUnit::Bytes)) {
        char text[32];
        std::snprintf(text, sizeof text, "%.0f", v);
        return text;
    }
    return number(v);
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

// Columns: the point, its axis values, then the table's sweep figures in table order (raw values).
void writeCsv(const fs::path& file, const Manifest& m, const std::vector<PointResult>& results,
              const metrics::FigureTable& table) {
    const std::vector<const metrics::FigureRow*> rows = metrics::figuresShown(metrics::InSweep, table);
    std::string text = "id,kind,label";
    for (const std::string& f : m.axisFields) text += "," + f;
    for (const metrics::FigureRow* row : rows) text += "," + row->key;
    text += "\n";
    for (const PointResult& r : results) {
        text += r.id + "," + (r.reference ? "reference" : "grid") + "," + csvField(r.label);
        for (const std::string& v : r.axisValues) text += "," + csvField(unquoted(v));
        for (const metrics::FigureRow* row : rows) text += "," + number(row->unit, r.figure(row->key));
        text += "\n";
    }
    writeTextAtomic(file, text);
}

nlohmann::ordered_json presetIn(const fs::path& folder, const Manifest& m, nlohmann::ordered_json settings) {
    return presetInFolder(folder, m.presetDir, std::move(settings));
}

std::string machineLine(const Manifest& m) { return m.machine.empty() ? "" : "machine: " + m.machine; }

std::vector<bool> frontOf(const std::vector<PointResult>& results, const std::string& xKey, const std::string& yKey) {
    std::vector<std::pair<double, double>> xy;
    for (const PointResult& r : results) xy.push_back({r.figure(xKey), r.figure(yKey)});
    return report::paretoFront(xy);
}

// A point's figure as charts show it (a share in %, bytes in MiB); NaN if absent.
double shownFigure(const PointResult& r, const metrics::FigureRow& row) {
    return metrics::shown(row.unit, r.figure(row.key));
}

std::string profileTitle(const std::string& profile) {
    if (profile.empty()) return "no cost profile";
    const std::string renderer = profile.substr(0, profile.find_first_of(" ,("));
    const std::size_t at = profile.find("calibrated ");
    return renderer + " profile" + (at == std::string::npos ? "" : " " + profile.substr(at + 11));
}

report::ScatterChart scatter(const Manifest& m, const std::vector<PointResult>& results, const metrics::FigureRow& x,
                             const metrics::FigureRow& y) {
    const std::string xShort = shortName(x), yShort = shortName(y);
    report::ScatterChart c;
    c.title = m.sweep + ", " + std::to_string(m.width) + "x" + std::to_string(m.height) + ": " + yShort +
              " against " + xShort;
    // A modelled cost is only as good as its profile: the title says which, short enough to fit
    // ("llvmpipe profile 2026-12-01"); results.json's manifest has the full name.
    if (x.key.rfind("cost.model", 0) == 0) c.title += " (" + profileTitle(m.costProfile) + ")";
    c.subtitle = std::to_string(results.size()) + " points, scene " + fs::path(m.scene).filename().string() + "; " +
                 machineLine(m);
    c.xLabel = x.axisTitle;
    c.yLabel = y.axisTitle;
    c.logY = true;
    const std::vector<bool> front = frontOf(results, x.key, y.key);
    c.tableHeader = {"front point", xShort, yShort};
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < results.size(); ++i) {
        const PointResult& r = results[i];
        c.points.push_back({shownFigure(r, x), shownFigure(r, y), r.label, front[i], r.reference});
        if (front[i]) order.push_back(i);
    }
    std::sort(order.begin(), order.end(), [&](auto a, auto b) { return results[a].figure(x.key) < results[b].figure(x.key); });
    for (const std::size_t i : order)
        c.tableRows.push_back({results[i].label, short3(shownFigure(results[i], x)), short3(shownFigure(results[i], y))});
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

// Per axis, the error, the cost and the memory along it (each figure once).
void writeAxisCharts(const fs::path& dir, const Manifest& m, const std::vector<PointResult>& results,
                     const std::vector<const metrics::FigureRow*>& figures) {
    for (std::size_t a = 0; a < m.axisFields.size(); ++a) {
        const auto line = alongAxis(m, results, a);
        std::string held;
        for (std::size_t b = 0; b < m.axisFields.size(); ++b)
            if (b != a) held += (held.empty() ? "others at " : ", ") + m.axisFields[b] + "=" + unquoted(m.baseValues[b]);
        for (const metrics::FigureRow* row : figures) {
            const std::string& key = row->key;
            report::LineChart c;
            c.title = m.sweep + ": " + key + " against " + m.axisFields[a];
            c.subtitle = held.empty() ? machineLine(m) : held + "; " + machineLine(m);
            c.xLabel = m.axisFields[a];
            c.yLabel = row->axisTitle;
            for (const std::string& v : m.axisValues[a]) c.xTickLabels.push_back(unquoted(v));
            report::Series s{key, {}, {}};
            for (std::size_t i = 0; i < line.size(); ++i)
                if (line[i] && std::isfinite(line[i]->figure(key))) s.x.push_back(double(i)), s.y.push_back(shownFigure(*line[i], *row));
            c.series.push_back(s);
            const std::string stem = "axis-" + m.axisFields[a] + "-" + key;
            report::writeLineChart(c, dir / (stem + ".png"), fs::path());
        }
    }
}

std::vector<std::string> writeFront(const fs::path& dir, const Manifest& m, const std::vector<PointResult>& results,
                                    const std::vector<bool>& front, const metrics::FigureRow& cost,
                                    const metrics::FigureRow& error) {
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
                        {cost.key, metrics::figureJson(cost.unit, r.figure(cost.key))},
                        {error.key, metrics::figureJson(error.unit, r.figure(error.key))}});
        ids.push_back(r.id);
    }
    writeTextAtomic(dir / "front.json", list.dump(2) + "\n");
    return ids;
}

}  // namespace

nlohmann::ordered_json presetInFolder(const fs::path& folder, const fs::path& presetDir, nlohmann::ordered_json settings) {
    const std::string scene = settings.value("scene", "");
    if (!scene.empty() && scene.rfind("builtin:", 0) != 0 && fs::path(scene).is_relative()) {
        const fs::path abs = (presetDir / scene).lexically_normal();
        const fs::path rel = abs.lexically_relative(fs::absolute(folder).lexically_normal());
        settings["scene"] = rel.empty() ? abs.string() : rel.string();
    }
    return settings;
}

std::vector<std::string> writeReport(const fs::path& dir, const Manifest& m, const std::vector<PointResult>& results,
                                     const ReportOptions& opt, const metrics::FigureTable& table) {
    const metrics::FigureRow& error = errorFigure(opt.error, table);
    const metrics::FigureRow& cost = costFigure(opt.cost, table);
    const metrics::FigureRow& memory = costFigure(kMemoryChoice, table);
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw std::runtime_error(dir.string() + ": cannot create output folder: " + ec.message());
    writeCsv(dir / "results.csv", m, results, table);
    nlohmann::ordered_json all = {{"manifest", toJson(m)}, {"points", nlohmann::ordered_json::array()}};
    for (const PointResult& r : results) all["points"].push_back(toJson(r));
    writeTextAtomic(dir / "results.json", all.dump(2) + "\n");
    report::writeScatterChart(scatter(m, results, cost, error), dir / "pareto.png", dir / "pareto.svg");
    report::writeScatterChart(scatter(m, results, memory, error), dir / "pareto-memory.png", dir / "pareto-memory.svg");
    std::vector<const metrics::FigureRow*> axisFigures{&error, &cost};
    if (&memory != &cost) axisFigures.push_back(&memory);
    writeAxisCharts(dir, m, results, axisFigures);
    return writeFront(dir, m, results, frontOf(results, cost.key, error.key), cost, error);
}

}  // namespace st::sweep
