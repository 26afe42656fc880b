#include "metrics/metrics_json.h"

#include "renderer/render/pass_work_json.h"

namespace st::metrics {
namespace {
using OJson = nlohmann::ordered_json;

OJson errorJson(const ErrorCounts& e) {
    return OJson{
        {"receivers", e.receivers},
        {"misclassified", e.share(e.misclassified())},
        {"falseShadow", e.share(e.falseShadow())},
        {"falseLight", e.share(e.falseLight())},
        {"edge", {{"falseShadow", e.share(e.falseShadowEdge)}, {"falseLight", e.share(e.falseLightEdge)}}},
        {"gross", {{"falseShadow", e.share(e.falseShadowGross)}, {"falseLight", e.share(e.falseLightGross)}}},
        {"grossPixels", e.gross()},
        {"filteredError", e.filteredError()},
        {"pixels",
         {{"falseShadowEdge", e.falseShadowEdge}, {"falseShadowGross", e.falseShadowGross},
          {"falseLightEdge", e.falseLightEdge}, {"falseLightGross", e.falseLightGross}}},
    };
}

OJson accuracyJson(const AccuracyReport& a) {
    OJson j = errorJson(a.all);
    j["coveredPixels"] = a.covered;
    j["facingAwayPixels"] = a.facingAway;
    j["terminatorPixels"] = a.terminator;
    j["truthEdgePixels"] = a.edgePixels;
    j["beyondShadowRange"] = errorJson(a.beyond);
    j["cascades"] = OJson::array();
    for (const ErrorCounts& c : a.cascades) j["cascades"].push_back(errorJson(c));
    return j;
}

OJson artifactJson(const ArtifactCounts& a) {
    return OJson{
        {"receivers", a.receivers},
        {"filteredError", a.filteredError()},
        {"acne", a.share(a.acne)},
        {"lightBleeding", a.share(a.lightBleeding)},
        {"peterPanning", a.share(a.peterPanning)},
        {"missingCaster", a.share(a.missingCaster)},
        {"edge", a.share(a.edge)},
        {"pixels",
         {{"acne", a.acne}, {"lightBleeding", a.lightBleeding}, {"peterPanning", a.peterPanning},
          {"missingCaster", a.missingCaster}, {"edge", a.edge}}},
    };
}

// The filtered result against the soft truth of the sun's disc (soft_accuracy.h).
OJson softJson(const PresetMeasurement& m) {
    OJson j = artifactJson(m.soft.all);
    j["angularDiameter"] = m.sun.angularDiameter;
    j["sunRays"] = m.sun.rays;
    j["seed"] = m.sun.seed;
    j["artifactTexels"] = m.settings.measure.artifactTexels;
    const PenumbraWidth& p = m.soft.penumbra;
    j["penumbraWidth"] = OJson{{"truthPx", p.truthPx},           {"filteredPx", p.filteredPx},
                               {"errorPx", p.errorPx()},         {"truthPixels", p.truthPixels},
                               {"truthContour", p.truthContour}, {"filteredPixels", p.filteredPixels},
                               {"filteredContour", p.filteredContour}};
    j["cascades"] = OJson::array();
    for (const ArtifactCounts& c : m.soft.cascades) j["cascades"].push_back(artifactJson(c));
    return j;
}

OJson densityJson(const DensityStats& d) {
    return OJson{{"pixels", d.pixels},   {"median", d.median},
                 {"p90", d.p90},         {"p95", d.p95},
                 {"max", d.max},         {"aliasingShare", d.aliasingShare},
                 {"wastedShare", d.wastedShare}};
}

OJson texelDensityJson(const DensityReport& r) {
    OJson j = densityJson(r.all);
    j["cascades"] = OJson::array();
    for (const DensityStats& c : r.cascades) j["cascades"].push_back(densityJson(c));
    return j;
}

OJson flickerJson(const FlickerReport& f) {
    return OJson{{"frames", f.frames},
                 {"samplePoints", f.samplePoints},
                 {"flipRate", f.flipRate},
                 {"maxFlipShare", f.maxFlipShare},
                 {"flickeringShare", f.flickeringShare},
                 {"meanHardStdDev", f.meanHardStdDev},
                 {"maxHardStdDev", f.maxHardStdDev},
                 {"meanFilteredStdDev", f.meanFilteredStdDev},
                 {"alternatingPixels", f.alternatingPixels}};
}

OJson costJson(const CostReport& c) {
    OJson j{{"timedFrames", c.frames},         {"gpuShadowMs", c.gpuShadowMs},   {"gpuMainMs", c.gpuMainMs},
            {"cpuMs", c.cpuMs},                {"shadowMapBytes", c.shadowMapBytes}, {"sceneTriangles", c.sceneTriangles},
            {"draws", c.draws},                {"casterTriangles", c.triangles}, {"texels", c.texels},
            {"texelsCovered", c.texelsCovered}, {"gpuFilterMs", c.gpuFilterMs},
            {"filterMapBytes", c.filterMapBytes}, {"cascades", OJson::array()}};
    for (const auto& [key, range] : {std::pair{"gpuShadow", c.gpuShadowRange}, std::pair{"gpuMain", c.gpuMainRange},
                                     std::pair{"gpuFilter", c.gpuFilterRange}, std::pair{"cpu", c.cpuRange}}) {
        j[std::string(key) + "MinMs"] = range.minMs;
        j[std::string(key) + "MaxMs"] = range.maxMs;
    }
    j["work"] = frameWorkJson(c.work);
    // The modelled figures themselves are the table's rows (cost.modelMs, cost.model.*Ms).
    j["profile"] = c.model ? OJson(c.profile) : OJson(nullptr);
    if (c.model) j["model"] = OJson{{"cascadesMs", c.model->cascadesMs}};
    for (const CascadeCost& k : c.cascades) {
        j["cascades"].push_back(OJson{{"draws", k.draws}, {"casterTriangles", k.triangles}, {"gpuMs", k.gpuMs},
                                      {"texels", k.texels}, {"texelsCovered", k.texelsCovered}});
    }
    return j;
}

OJson timingsJson(const MeasureTimings& t) {
    return OJson{{"bvhMs", t.bvhMs},         {"groundTruthMs", t.groundTruthMs}, {"softTruthMs", t.softTruthMs},
                 {"measurePassMs", t.measurePassMs},
                 {"costMs", t.costMs},       {"flickerMs", t.flickerMs},         {"totalMs", t.totalMs}};
}

// The table's figures at their paths. An absent figure whose section is absent (flicker without
// a path: "flicker": null) stays absent; one inside a present section is null.
void setFigures(OJson& j, const PresetMeasurement& m, const FigureTable& table) {
    for (const FigureValue& f : readFigures(m, InMetricsJson, table)) {
        const OJson::json_pointer at(jsonPointer(f.row->key));
        if (!f.value && (!j.contains(at.parent_pointer()) || !j.at(at.parent_pointer()).is_object())) continue;
        j[at] = figureJson(f.row->unit, f.value);
    }
}

}  // namespace

OJson toJson(const PresetMeasurement& m, const std::string& presetName, const FigureTable& table) {
    OJson j{{"preset", presetName},
            {"scene", m.settings.scene},
            {"width", m.samples.width},
            {"height", m.samples.height},
            {"cascades", m.settings.cascades.count},
            {"mapSize", m.settings.cascades.mapSize},
            {"accuracy", accuracyJson(m.accuracy)},
            {"soft", softJson(m)},
            {"texelDensity", texelDensityJson(m.density)},
            {"flicker", m.flicker ? flickerJson(*m.flicker) : OJson(nullptr)},
            {"cost", m.cost ? costJson(*m.cost) : OJson(nullptr)},
            {"frame", OJson::parse(toJsonText(m.frame))},
            {"warnings", m.warnings},
            {"timings", timingsJson(m.timings)}};
    setFigures(j, m, table);
    return j;
}

}  // namespace st::metrics
