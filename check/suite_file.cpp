#include "check/suite_file.h"

#include <nlohmann/json.hpp>

#include <fnmatch.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>

namespace st::check {
namespace fs = std::filesystem;
using nlohmann::json;

SuiteError::SuiteError(fs::path file, std::string jsonPath, std::string reason)
    : std::runtime_error(file.string() + ": " + (jsonPath.empty() ? "/" : jsonPath) + ": " + reason),
      file_(std::move(file)), path_(std::move(jsonPath)), reason_(std::move(reason)) {}

namespace {

std::string shortNumber(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

// Reads one suite; `fail` throws with the file.
struct Reader {
    fs::path file;

    [[noreturn]] void fail(const std::string& path, const std::string& reason) const { throw SuiteError(file, path, reason); }

    void onlyKeys(const json& j, const std::string& path, const std::set<std::string>& keys) const {
        if (!j.is_object()) fail(path, "expected an object");
        for (const auto& [k, v] : j.items())
            if (!keys.count(k)) {
                std::string list;
                for (const std::string& key : keys) list += (list.empty() ? "" : ", ") + key;
                fail(path + "/" + k, "unknown key (expected one of " + list + ")");
            }
    }

    double number(const json& j, const std::string& path, double lo, double hi) const {
        if (!j.is_number()) fail(path, "expected a number");
        const double v = j.get<double>();
        if (!(v >= lo && v <= hi)) fail(path, "must be in " + shortNumber(lo) + ".." + shortNumber(hi) + ", got " + j.dump());
        return v;
    }

    std::string text(const json& j, const std::string& path) const {
        if (!j.is_string()) fail(path, "expected a string");
        return j.get<std::string>();
    }

    std::pair<int, int> size(const json& j, const std::string& path) const {
        const std::string s = text(j, path);
        int w = 0, h = 0;
        char rest = 0;
        if (std::sscanf(s.c_str(), "%dx%d%c", &w, &h, &rest) != 2 || w < 16 || h < 16 || w > 8192 || h > 8192)
            fail(path, "expected WxH with 16..8192 each, got '" + s + "'");
        return {w, h};
    }

    void image(const json& j, const std::string& path, ImageTolerance& t) const {
        onlyKeys(j, path, {"max_channel_diff", "max_failing_share"});
        if (j.contains("max_channel_diff")) {
            if (!j["max_channel_diff"].is_number_integer()) fail(path + "/max_channel_diff", "expected an integer");
            t.maxChannelDiff = int(number(j["max_channel_diff"], path + "/max_channel_diff", 0, 255));
        }
        if (j.contains("max_failing_share")) t.maxFailingShare = number(j["max_failing_share"], path + "/max_failing_share", 0, 1);
    }

    FigureTolerance figure(const json& j, const std::string& path) const {
        if (!j.is_object()) fail(path, "expected {\"figure\": NAME, RULE: NUMBER}");
        if (!j.contains("figure")) fail(path + "/figure", "missing: the figure's name (docs/metrics.md)");
        FigureTolerance t;
        try {
            t.row = &figureNamed(text(j["figure"], path + "/figure"));
        } catch (const std::invalid_argument& e) {
            fail(path + "/figure", e.what());
        }
        int rules = 0;
        for (const auto& [k, v] : j.items()) {
            if (k == "figure") continue;
            const auto rule = ruleOfKey(k);
            if (!rule) fail(path + "/" + k, "unknown key (expected figure and one of max, min, worse_by_at_most, "
                                            "worse_by_at_most_pp, worse_by_at_most_factor)");
            t.rule = *rule;
            t.limit = number(v, path + "/" + k, -1e300, 1e300);
            if (const std::string why = ruleProblem(*t.row, t.rule, t.limit); !why.empty()) fail(path + "/" + k, why);
            ++rules;
        }
        if (rules != 1) fail(path, "give exactly one rule (max, min, worse_by_at_most, worse_by_at_most_pp, "
                                   "worse_by_at_most_factor), got " + std::to_string(rules));
        return t;
    }

    std::vector<FigureTolerance> figures(const json& j, const std::string& path) const {
        if (!j.is_array()) fail(path, "expected an array of figure tolerances");
        std::vector<FigureTolerance> out;
        for (std::size_t i = 0; i < j.size(); ++i) {
            FigureTolerance t = figure(j[i], path + "/" + std::to_string(i));
            for (const FigureTolerance& o : out)
                if (o.row == t.row) fail(path + "/" + std::to_string(i), t.row->key + " is listed twice");
            out.push_back(t);
        }
        return out;
    }

    OnRendererMismatch mismatch(const json& j, const std::string& path) const {
        const std::string s = text(j, path);
        if (s == "fail") return OnRendererMismatch::Fail;
        if (s == "compare") return OnRendererMismatch::Compare;
        fail(path, "expected \"fail\" or \"compare\", got '" + s + "'");
    }

    // Fills the fields an entry and the defaults share.
    void common(const json& j, const std::string& path, SuiteEntry& e) const {
        if (j.contains("size")) e.size = size(j["size"], path + "/size");
        if (j.contains("image")) image(j["image"], path + "/image", e.image);
        if (j.contains("on_renderer_mismatch")) e.onRendererMismatch = mismatch(j["on_renderer_mismatch"], path + "/on_renderer_mismatch");
        if (j.contains("figures")) {
            for (const FigureTolerance& t : figures(j["figures"], path + "/figures")) {
                auto same = std::find_if(e.figures.begin(), e.figures.end(), [&](const FigureTolerance& o) { return o.row == t.row; });
                if (same != e.figures.end()) *same = t;
                else e.figures.push_back(t);
            }
        }
    }

    // The presets a path or glob names, relative to the suite's folder; a glob's wildcards
    // may be in its last part only.
    std::vector<fs::path> presetsOf(const std::string& pattern, const std::string& path) const {
        if (pattern.empty()) fail(path, "empty preset path");
        const fs::path p = file.parent_path() / pattern;
        const std::string last = p.filename().string();
        if (p.parent_path().string().find_first_of("*?[") != std::string::npos)
            fail(path, "wildcards are allowed in the file name only: '" + pattern + "'");
        if (last.find_first_of("*?[") == std::string::npos) {
            if (!fs::is_regular_file(p)) fail(path, "no such preset: " + p.string());
            return {p};
        }
        std::vector<fs::path> out;
        std::error_code ec;
        for (const auto& de : fs::directory_iterator(p.parent_path(), ec))
            if (de.is_regular_file() && fnmatch(last.c_str(), de.path().filename().c_str(), 0) == 0) out.push_back(de.path());
        if (ec) fail(path, "cannot list " + p.parent_path().string() + ": " + ec.message());
        if (out.empty()) fail(path, "'" + pattern + "' matches no file in " + p.parent_path().string());
        std::sort(out.begin(), out.end());
        return out;
    }

    Suite read(const json& root) const {
        onlyKeys(root, "", {"$schema", "version", "notes", "defaults", "presets"});
        if (!root.contains("version")) fail("/version", "missing (this program reads version " + std::to_string(kSuiteVersion) + ")");
        if (root["version"] != kSuiteVersion)
            fail("/version", "unsupported version " + root["version"].dump() + " (this program reads " + std::to_string(kSuiteVersion) + ")");
        if (root.contains("notes")) text(root["notes"], "/notes");
        SuiteEntry defaults;
        if (root.contains("defaults")) {
            onlyKeys(root["defaults"], "/defaults", {"size", "image", "figures", "on_renderer_mismatch"});
            common(root["defaults"], "/defaults", defaults);
        }
        if (!root.contains("presets")) fail("/presets", "missing: the presets to check");
        const json& list = root["presets"];
        if (!list.is_array() || list.empty()) fail("/presets", "expected a non-empty array of presets or globs");
        Suite suite{file, {}};
        std::map<fs::path, std::size_t> seen;  // a later entry replaces an earlier one of the same preset
        std::map<std::string, fs::path> names;
        for (std::size_t i = 0; i < list.size(); ++i) {
            const std::string path = "/presets/" + std::to_string(i);
            const json& item = list[i];
            SuiteEntry e = defaults;
            std::string pattern;
            if (item.is_string()) {
                pattern = item.get<std::string>();
            } else {
                onlyKeys(item, path, {"preset", "size", "image", "figures", "on_renderer_mismatch", "note"});
                if (!item.contains("preset")) fail(path + "/preset", "missing: a preset path or glob");
                pattern = text(item["preset"], path + "/preset");
                common(item, path, e);
                if (item.contains("note")) e.note = text(item["note"], path + "/note");
            }
            for (const fs::path& p : presetsOf(pattern, path)) {
                SuiteEntry one = e;
                one.preset = p.lexically_normal();
                one.name = p.stem().string();
                const fs::path key = fs::weakly_canonical(p);
                if (auto n = names.find(one.name); n != names.end() && n->second != key)
                    fail(path, "two presets are named '" + one.name + "' (" + n->second.string() + ", " + key.string() +
                                   "); goldens are kept by name");
                names[one.name] = key;
                if (auto s = seen.find(key); s != seen.end()) suite.entries[s->second] = one;
                else {
                    seen[key] = suite.entries.size();
                    suite.entries.push_back(one);
                }
            }
        }
        return suite;
    }
};

}  // namespace

Suite loadSuite(const fs::path& file) {
    const Reader r{file};
    std::ifstream in(file);
    if (!in) r.fail("", "cannot open the suite file");
    json root;
    try {
        root = json::parse(in);
    } catch (const json::parse_error& e) {
        r.fail("", std::string("not valid JSON: ") + e.what());
    }
    return r.read(root);
}

std::vector<SuiteEntry> selectEntries(const std::vector<SuiteEntry>& entries, const std::string& pattern) {
    if (pattern.empty()) return entries;
    std::vector<SuiteEntry> out;
    for (const SuiteEntry& e : entries)
        if (fnmatch(pattern.c_str(), e.name.c_str(), 0) == 0) out.push_back(e);
    return out;
}

}  // namespace st::check
