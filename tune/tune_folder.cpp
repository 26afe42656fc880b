// The tune's folder: claimed by one tune, resumed from its earlier runs; and the text of its figures.
#include "tune/tuner.h"

#include "metrics/cost.h"
#include "metrics/figure_table.h"
#include "renderer/export/engine_snippets.h"
#include "renderer/image/image_io.h"
#include "renderer/settings/settings_json.h"
#include "renderer/settings/validation.h"
#include "sweep/sweep_results.h"
#include "sweep/sweep_spec.h"
#include "tune/tune_engine.h"
#include "tune/tune_eval.h"
#include "tune/tune_explain.h"
#include "tune/tune_holdout.h"
#include "tune/tune_journal.h"
#include "tune/tune_views.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <thread>

namespace st::tune::detail {

std::string fixed(double v, int decimals) {
    char text[48];
    std::snprintf(text, sizeof text, "%.*f", decimals, v);
    return text;
}

std::string errorText(const std::string& choice, double raw) {
    const metrics::FigureRow& row = sweep::errorFigure(choice);
    const metrics::UnitInfo& u = metrics::unitInfo(row.unit);
    char text[48];
    std::snprintf(text, sizeof text, "%.4g", raw * u.scale);  // errors span 1e-5 .. 1: significant digits
    return text + (u.symbol[0] ? " " + std::string(u.symbol) : "");
}

std::string budgetText(const Budget& b) {
    std::string t;
    if (b.ms) t += fixed(*b.ms, 1) + " ms";
    if (b.bytes) t += (t.empty() ? "" : " and ") + fixed(*b.bytes / kMiB, 1) + " MiB";
    return t;
}

void claimFolder(const fs::path& dir, const Json& identity) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir))
        throw std::runtime_error(dir.string() + ": cannot create output folder: " + (ec ? ec.message() : "not a directory"));
    const fs::path file = dir / "tune.json";
    if (std::ifstream in(file); in) {
        Json there;
        try {
            there = Json::parse(in);
        } catch (const nlohmann::json::exception& e) {
            throw std::runtime_error(file.string() + ": not valid JSON: " + e.what());
        }
        if (there != identity)
            throw std::runtime_error(dir.string() + ": holds another tune (another preset, objective, budget, views, "
                                     "seed or profile; see its tune.json); give another --out or remove it");
        return;
    }
    writeTextAtomic(file, identity.dump(2) + "\n");
}

EarlierRuns earlierRuns(const fs::path& dir) {
    EarlierRuns out;
    std::ifstream in(dir / "progress.json");
    if (!in) return out;
    try {
        const Json j = Json::parse(in);
        if (const auto it = j.find("secondsAllRuns"); it != j.end() && it->is_number() && it->get<double>() >= 0.0)
            out.seconds = it->get<double>();
        for (const auto& [key, scale] : {std::pair<const char*, int>{"screeningLimit", 1}, {"limit", kScreensPerEvaluation}})
            if (const auto it = j.find(key); it != j.end() && it->is_number_integer() && it->get<int>() > 0) {
                out.screeningLimit = it->get<int>() * scale;
                break;
            }
    } catch (const nlohmann::json::exception&) {
    }
    return out;
}

}  // namespace st::tune::detail
