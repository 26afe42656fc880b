#include "check/results_json.h"

namespace st::check {
using OJson = nlohmann::ordered_json;
namespace {

OJson value(const metrics::FigureRow& row, std::optional<double> v) { return metrics::figureJson(row.unit, v); }

OJson imageJson(const PresetResult& r) {
    if (!r.image) return nullptr;
    const ImageDiff& d = *r.image;
    OJson j{{"pass", d.pass}, {"sizeMatches", d.sizeMatches}, {"maxChannelDiff", d.maxChannelDiff},
            {"failingPixels", d.failingPixels}, {"failingShare", d.failingShare}, {"tolerance", r.imageTolerance}};
    return j;
}

OJson figureJson(const FigureRowResult& f) {
    OJson j{{"key", f.row->key}, {"label", f.row->label}, {"golden", value(*f.row, f.golden)}, {"actual", value(*f.row, f.actual)}};
    j["delta"] = f.golden && f.actual ? OJson(*f.actual - *f.golden) : OJson(nullptr);
    if (f.verdict) j["check"] = OJson{{"rule", f.verdict->rule}, {"pass", f.verdict->pass}, {"message", f.verdict->message}};
    return j;
}

}  // namespace

OJson resultsJson(const RunInfo& info, const std::vector<PresetResult>& results) {
    OJson presets = OJson::array();
    int failures = 0;
    for (const PresetResult& r : results) {
        failures += isFailure(r.status) ? 1 : 0;
        OJson figures = OJson::array();
        for (const FigureRowResult& f : r.figures) figures.push_back(figureJson(f));
        OJson p{{"name", r.name},         {"preset", r.preset},     {"status", statusName(r.status)},
                {"failure", isFailure(r.status)}, {"message", r.message}, {"notes", r.notes},
                {"note", r.note},         {"golden", r.goldenDir},  {"seconds", r.seconds},
                {"image", imageJson(r)},  {"figures", figures}};
        if (!r.diffPng.empty()) p["images"] = OJson{{"golden", r.goldenPng}, {"actual", r.actualPng}, {"diff", r.diffPng}};
        presets.push_back(p);
    }
    return OJson{{"version", 1},
                 {"suite", info.suite},
                 {"golden", info.golden},
                 {"renderer", info.renderer},
                 {"product", info.version},
                 {"update", info.update},
                 {"presets", results.size()},
                 {"failures", failures},
                 {"exitCode", exitCodeOf(results)},
                 {"results", presets}};
}

}  // namespace st::check
