#include "check/suite_schema.h"

#include "check/figure_check.h"
#include "check/suite_file.h"

#include <nlohmann/json.hpp>

namespace st::check {
namespace {
using OJson = nlohmann::ordered_json;

OJson figureNames() {
    OJson names = OJson::array();
    for (const metrics::FigureRow& r : metrics::figureTable())
        if (!r.timing) names.push_back(r.key);
    return names;
}

OJson figureToleranceSchema() {
    OJson rules = OJson::array();
    for (FigureRule r : {FigureRule::Max, FigureRule::Min, FigureRule::WorseByAtMost, FigureRule::WorseByAtMostPp,
                         FigureRule::WorseByAtMostFactor})
        rules.push_back(OJson{{"required", {ruleKey(r)}}});
    return {{"type", "object"},
            {"description", "One figure's tolerance: exactly one rule. The figure is its key (below), its sweep choice "
                            "name, its key as one camel-case word (softFilteredError) or its key's last part when unique."},
            {"properties",
             {{"figure", {{"type", "string"}, {"examples", figureNames()}}},
              {"max", {{"type", "number"}, {"description", "value <= max"}}},
              {"min", {{"type", "number"}, {"description", "value >= min"}}},
              {"worse_by_at_most", {{"type", "number"}, {"minimum", 0}, {"description", "worse than the golden by at most this, in the raw unit"}}},
              {"worse_by_at_most_pp", {{"type", "number"}, {"minimum", 0}, {"description", "a share, worse than the golden by at most this many percentage points"}}},
              {"worse_by_at_most_factor", {{"type", "number"}, {"minimum", 1}, {"description", "worse than the golden by at most this factor"}}}}},
            {"required", {"figure"}},
            {"oneOf", rules},
            {"additionalProperties", false}};
}

OJson commonProperties() {
    return {{"size", {{"type", "string"}, {"pattern", "^[0-9]+x[0-9]+$"}, {"description", "WxH, 16..8192 each: replaces the preset's output size"}}},
            {"image",
             {{"type", "object"},
              {"properties",
               {{"max_channel_diff", {{"type", "integer"}, {"minimum", 0}, {"maximum", 255}, {"default", 5}}},
                {"max_failing_share", {{"type", "number"}, {"minimum", 0}, {"maximum", 1}, {"default", 0.001}}}}},
              {"additionalProperties", false}}},
            {"figures", {{"type", "array"}, {"items", {{"$ref", "#/$defs/figureTolerance"}}}}},
            {"on_renderer_mismatch", {{"enum", {"fail", "compare"}}, {"default", "fail"}}}};
}
}  // namespace

std::string suiteJsonSchemaText() {
    OJson entryProps = commonProperties();
    entryProps["preset"] = {{"type", "string"}, {"description", "a preset or a glob (wildcards in the file name), relative to the suite"}};
    entryProps["note"] = {{"type", "string"}};
    const OJson entryObject{{"type", "object"}, {"properties", entryProps}, {"required", {"preset"}}, {"additionalProperties", false}};
    const OJson entry{{"oneOf", OJson::array({OJson{{"type", "string"}}, entryObject})}};
    OJson props = OJson::object();
    props["$schema"] = {{"type", "string"}};
    props["version"] = {{"const", kSuiteVersion}};
    props["notes"] = {{"type", "string"}};
    props["defaults"] = {{"type", "object"}, {"properties", commonProperties()}, {"additionalProperties", false}};
    props["presets"] = {{"type", "array"}, {"minItems", 1}, {"items", entry}};
    OJson root = OJson::object();
    root["$schema"] = "https://json-schema.org/draft/2020-12/schema";
    root["title"] = "shadowtune check suite";
    root["description"] = "Presets replayed by `shadowtune check` against their goldens, with image and figure tolerances. "
                          "Generated from check/suite_schema.cpp and the figures table.";
    root["type"] = "object";
    root["properties"] = props;
    root["required"] = {"version", "presets"};
    root["additionalProperties"] = false;
    root["$defs"] = {{"figureTolerance", figureToleranceSchema()}};
    return root.dump(2) + "\n";
}

}  // namespace st::check
