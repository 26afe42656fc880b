#include "app/cli/tune_engine_proof.h"

#include "app/cli/engine_check_command.h"
#include "app/editor/child_run.h"
#include "renderer/image/image_io.h"
#include "renderer/settings/settings_json.h"
#include "tune/tune_views.h"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace st::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kProofKeys[] = {"accuracy.misclassified", "soft.filteredError"};

json readJsonFile(const fs::path& file) {
    std::ifstream in(file);
    if (!in) throw std::runtime_error(file.string() + ": cannot be read");
    json j = json::parse(in, nullptr, false);
    if (j.is_discarded()) throw std::runtime_error(file.string() + ": not JSON");
    return j;
}

// The checks' figures.json over a group of views, weighted by each view's scored pixels (a view
// whose camera sees no sun-facing receiver scores none and counts for nothing): the engine's
// figures under the figure-table keys, the pixel and factor agreements, the model's beside.
json meanFigures(const std::vector<json>& checks) {
    double pixels = 0.0;
    for (const json& c : checks) pixels += c.value("scoredPixels", 0.0);
    json out = {{"views", checks.size()}, {"scoredPixels", pixels}};
    if (pixels <= 0.0) return out;
    const auto mean = [&](auto get) {
        double sum = 0.0;
        for (const json& c : checks) sum += c.value("scoredPixels", 0.0) * get(c);
        return sum / pixels;
    };
    for (const char* key : kProofKeys) {
        out[key] = mean([&](const json& c) { return c.at("engine").at("figures").at(key).get<double>(); });
        out["model"][key] = mean([&](const json& c) { return c.at("model").at("figures").at(key).get<double>(); });
    }
    out["agreement"] = mean([](const json& c) { return c.at("agreement").get<double>(); });
    out["factorAgreement"] = mean([](const json& c) { return c.value("factorAgreement", 0.0); });
    return out;
}

std::string pct(double share) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3f %%", 100.0 * share);
    return b;
}

std::string num(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.4f", v);
    return b;
}

std::string tableRow(const std::string& settings, const std::string& views, const json& g) {
    if (g.value("views", 0) == 0 || !g.contains("agreement")) return "";
    return "| " + settings + " | " + views + " (" + std::to_string(g.at("views").get<int>()) + ") | " +
           pct(g.at("accuracy.misclassified")) + " / " + pct(g.at("model").at("accuracy.misclassified")) + " | " +
           num(g.at("soft.filteredError")) + " / " + num(g.at("model").at("soft.filteredError")) + " | " +
           pct(g.at("agreement")) + " |\n";
}

std::string explainSection(const json& e) {
    const std::string engine = e.at("name").get<std::string>() + " " + e.at("version").get<std::string>();
    std::string md = "\n## In the engine itself: " + engine + "\n\n";
    md += "Measured by `engine-check` in the real engine (headless Chromium) on the tune's views, the engine's figure "
          "first and shadowtune's model of the same knobs second; the agreement is the share of scored pixels on "
          "which the two say the same (docs/engines.md).\n\n";
    md += "| settings | views | misclassified: engine / model | filtered error: engine / model | pixel agreement |\n";
    md += "|---|---|---|---|---|\n";
    for (const char* group : {"tuned", "heldOut"}) {
        const std::string views = std::string(group) == "tuned" ? "tuned" : "held out";
        md += tableRow(e.at("name").get<std::string>() + " defaults", views, e.at("defaults").at(group));
        md += tableRow("tuned", views, e.at("tuned").at(group));
    }
    return md;
}

std::string summaryLine(const json& e) {
    const json& d = e.at("defaults").at("tuned");
    const json& t = e.at("tuned").at("tuned");
    std::string line = "in " + e.at("name").get<std::string>() + " " + e.at("version").get<std::string>() +
                       " itself: misclassified " + pct(d.at("accuracy.misclassified")) + " with its defaults -> " +
                       pct(t.at("accuracy.misclassified")) + " tuned on the tuned views";
    const json& dh = e.at("defaults").at("heldOut");
    const json& th = e.at("tuned").at("heldOut");
    if (dh.contains("agreement") && th.contains("agreement"))
        line += " (held out: " + pct(dh.at("accuracy.misclassified")) + " -> " + pct(th.at("accuracy.misclassified")) + ")";
    line += "; shadowtune's model agrees on " + pct(t.at("agreement")) + " of the pixels";
    return line;
}

}  // namespace

EngineProof proveInEngine(const TuneCommandOptions& opt) {
    EngineProof proof;
    if (!opt.engine || !xport::runsHere(*opt.engine) || opt.noEngineCheck) return proof;
    proof.ran = true;
    const fs::path dir = opt.outDir / "engine-check";
    try {
        Settings tuned = loadPreset(opt.outDir / "tuned.json");
        tuned.scene = absoluteScene(tuned.scene, opt.outDir);
        const json knobs = readJsonFile(opt.outDir / (xport::engineName(*opt.engine) + ".json")).at("knobs");
        fs::create_directories(dir);
        writeTextAtomic(dir / "tuned-knobs.json", knobs.dump(2) + "\n");
        const std::vector<tune::View> views = tune::tuneViews(tuned, opt.views, opt.holdOutEvery);
        json groups = {{"defaults", json::object()}, {"tuned", json::object()}};
        std::string version = "?";
        for (const char* which : {"defaults", "tuned"}) {
            std::vector<json> onTuned, onHeldOut;
            for (std::size_t i = 0; i < views.size(); ++i) {
                const fs::path view = dir / ("view-" + std::to_string(i + 1) + ".json");
                savePresetAtomic(tune::onView(tuned, views[i]), view);
                EngineCheckOptions o;
                o.preset = view;
                o.engine = *opt.engine;
                o.outDir = dir / which / ("view-" + std::to_string(i + 1));
                o.defaults = std::string(which) == "defaults";
                if (!o.defaults) o.knobsFile = dir / "tuned-knobs.json";
                o.quiet = true;
                std::fprintf(stderr, "engine-check: %s knobs on view %zu of %zu (%s)\n", which, i + 1, views.size(), views[i].name.c_str());
                if (const int rc = runEngineCheck(o); rc != 0)
                    throw std::runtime_error("engine-check of the " + std::string(which) + " knobs on view " + std::to_string(i + 1) +
                                             " exited " + std::to_string(rc) + " (see " + (o.outDir / "engine.log").string() + ")");
                json f = readJsonFile(o.outDir / "figures.json");
                version = f.at("engine").value("version", version);
                (views[i].heldOut ? onHeldOut : onTuned).push_back(std::move(f));
            }
            groups[which] = {{"tuned", meanFigures(onTuned)}, {"heldOut", meanFigures(onHeldOut)}};
        }
        proof.summary = {{"name", xport::engineName(*opt.engine)}, {"version", version},
                         {"defaults", groups["defaults"]}, {"tuned", groups["tuned"]},
                         {"checks", (dir).string()}};
        json summary = readJsonFile(opt.outDir / "summary.json");
        summary["engine"] = proof.summary;
        writeTextAtomic(opt.outDir / "summary.json", summary.dump(2) + "\n");
        std::ifstream in(opt.outDir / "explain.md");
        std::stringstream md;
        md << in.rdbuf();
        writeTextAtomic(opt.outDir / "explain.md", md.str() + explainSection(proof.summary));
        proof.line = summaryLine(proof.summary);
    } catch (const std::exception& e) {
        proof.error = e.what();
    }
    return proof;
}

}  // namespace st::app
