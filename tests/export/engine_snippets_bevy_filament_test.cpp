// renderer/export/engine_snippets_bevy_filament.cpp: the pasted Rust and C++ read back, by readers
// written here from the engines' own syntax (Rust struct literals `name: value`, C++ assignments
// `options.name = value;`), independent of the writer, to exactly the knobs they were written from.
#include "renderer/export/engine_knobs.h"
#include "renderer/export/engine_snippets.h"
#include "renderer/settings/settings_json.h"

#include <gtest/gtest.h>

#include <regex>
#include <stdexcept>
#include <string>

namespace st::xport {
namespace {

using nlohmann::json;

std::string bfPasted(Engine e, const json& knobs, const std::string& file) {
    for (const PasteText& t : engineSnippets(e, knobs))
        if (t.file == file) return t.text;
    ADD_FAILURE() << "no " << file;
    return "";
}

// A Rust or C++ number literal (`150.0`, `0.001f`, `2048`) as JSON; anything else throws.
json bfLiteral(std::string t) {
    if (!t.empty() && t.back() == 'f') t.pop_back();
    if (t == "true" || t == "false") return t == "true";
    std::size_t used = 0;
    const double v = std::stod(t, &used);
    if (used != t.size()) throw std::invalid_argument("not a number: " + t);
    return v;
}

// Bevy: every `name: value` of the struct literals, the bounds' vec![..], the filter's variant.
json readBevy(const std::string& rs) {
    json k = json::object();
    const std::regex field(R"(\b(shadow_depth_bias|shadow_normal_bias|overlap_proportion|minimum_distance): ([-0-9.eE+]+),)");
    for (std::sregex_iterator it(rs.begin(), rs.end(), field), end; it != end; ++it) k[(*it)[1].str()] = bfLiteral((*it)[2]);
    std::smatch m;
    if (std::regex_search(rs, m, std::regex(R"(DirectionalLightShadowMap \{ size: (\d+) \})")))
        k["shadow_map_size"] = std::stoi(m[1]);
    if (std::regex_search(rs, m, std::regex(R"(bounds: vec!\[([^\]]*)\])"))) {
        k["bounds"] = json::array();
        const std::string list = m[1];
        const std::regex number(R"([-0-9.eE+]+)");
        for (std::sregex_iterator it(list.begin(), list.end(), number), end; it != end; ++it) k["bounds"].push_back(bfLiteral(it->str()));
    }
    if (std::regex_search(rs, m, std::regex(R"(ShadowFilteringMethod::(\w+)\))"))) k["shadow_filtering_method"] = m[1].str();
    return k;
}

// Filament: `options.name = value;` and `options.cascadeSplitPositions[i] = value;`, the shadow type.
json readFilament(const std::string& cpp) {
    json k = json::object();
    const std::regex assignment(R"(options\.(\w+)(?:\[(\d)\])? = ([^;]+);)");
    for (std::sregex_iterator it(cpp.begin(), cpp.end(), assignment), end; it != end; ++it) {
        const std::string name = (*it)[1];
        if ((*it)[2].matched) k[name][std::stoul((*it)[2])] = bfLiteral((*it)[3]);
        else k[name] = bfLiteral((*it)[3]);
    }
    std::smatch m;
    if (std::regex_search(cpp, m, std::regex(R"(setShadowType\(View::ShadowType::(\w+)\))"))) k["shadowType"] = m[1].str();
    return k;
}

// The knobs as numbers compare: 2048 and 2048.0 are one value to the engines' parsers.
void bfExpectSameKnobs(const json& read, const json& knobs, const std::string& what) {
    EXPECT_EQ(read.size(), knobs.size()) << what << " read " << read.dump() << "\nwrote " << knobs.dump();
    for (auto it = knobs.begin(); it != knobs.end(); ++it) {
        ASSERT_TRUE(read.contains(it.key())) << what << ": " << it.key() << " missing from the text";
        EXPECT_EQ(read.at(it.key()), it.value()) << what << ": " << it.key();
    }
}

TEST(EngineSnippetsTest, BevyRustReadsBackToItsKnobs) {
    const Settings yard = loadPreset(ST_PRESET_DIR "/default.json");
    json tuned = defaultKnobs(Engine::Bevy);
    tuned["bounds"] = {3.5, 12.0, 150};  // an integer bound must still print as an f32 literal
    tuned["overlap_proportion"] = 0.05;
    tuned["shadow_depth_bias"] = 0.005;
    tuned["shadow_normal_bias"] = 0.0001;
    tuned["shadow_map_size"] = 4096;
    tuned["shadow_filtering_method"] = "Temporal";
    for (const json& k : {defaultKnobs(Engine::Bevy), tuned, knobsFor(Engine::Bevy, engineModel(Engine::Bevy, tuned, yard)).knobs}) {
        const std::string rs = bfPasted(Engine::Bevy, k, "bevy.rs");
        bfExpectSameKnobs(readBevy(rs), k, "bevy.rs");
        EXPECT_EQ(rs.find("150]"), std::string::npos) << "Rust does not coerce 150 to f32 in vec![..]";
    }
}

TEST(EngineSnippetsTest, FilamentCppReadsBackToItsKnobs) {
    json tuned = defaultKnobs(Engine::Filament);
    tuned["shadowCascades"] = 3;
    tuned["cascadeSplitPositions"] = {0.05, 0.2, 0.6};
    tuned["shadowFar"] = 120;
    tuned["stable"] = true;
    tuned["lispsm"] = false;
    tuned["constantBias"] = 0.00002;
    tuned["shadowType"] = "VSM";
    for (const json& k : {defaultKnobs(Engine::Filament), tuned}) {
        const std::string cpp = bfPasted(Engine::Filament, k, "filament.cpp");
        bfExpectSameKnobs(readFilament(cpp), k, "filament.cpp");
        EXPECT_NE(cpp.find("options.constantBias = "), std::string::npos);
    }
}

// The readers are not lenient: a text whose knob is misspelt does not read back, and a misspelt
// knob given to the tables is refused rather than falling back to a default.
TEST(EngineSnippetsTest, AMisspeltKnobIsRefused) {
    std::string rs = bfPasted(Engine::Bevy, defaultKnobs(Engine::Bevy), "bevy.rs");
    rs.replace(rs.find("shadow_depth_bias"), 17, "shadow_dept_bias");
    EXPECT_FALSE(readBevy(rs).contains("shadow_depth_bias"));
    std::string cpp = bfPasted(Engine::Filament, defaultKnobs(Engine::Filament), "filament.cpp");
    cpp.replace(cpp.find("options.normalBias"), 18, "options.normalBais");
    const json read = readFilament(cpp);
    EXPECT_TRUE(read.contains("normalBais"));
    EXPECT_THROW(engineModel(Engine::Filament, read, loadPreset(ST_PRESET_DIR "/default.json")), std::invalid_argument);
    json k = defaultKnobs(Engine::Bevy);
    k["shadow_map_sise"] = 1024;
    EXPECT_THROW(engineModel(Engine::Bevy, k, loadPreset(ST_PRESET_DIR "/default.json")), std::invalid_argument);
}

}  // namespace
}  // namespace st::xport
