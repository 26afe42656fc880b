#include "tests/support/golden_tolerance.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace st::test {
namespace {

[[noreturn]] void fail(const std::string& where, const std::string& what) {
    throw std::runtime_error("golden tolerances: " + where + ": " + what);
}

void expectOnly(const nlohmann::json& object, std::initializer_list<std::string_view> keys, const std::string& where) {
    if (!object.is_object()) fail(where, "expected an object, got " + object.dump());
    for (const auto& [key, value] : object.items())
        if (std::find(keys.begin(), keys.end(), key) == keys.end()) fail(where + "." + key, "unknown key");
}

GoldenTolerance parseEntry(const nlohmann::json& entry, const std::string& where) {
    expectOnly(entry, {"maxChannelDiff", "maxFailingFraction", "reason"}, where);
    GoldenTolerance t;
    const auto diff = entry.value("maxChannelDiff", nlohmann::json());
    const auto share = entry.value("maxFailingFraction", nlohmann::json());
    if (!diff.is_number_integer() || diff.get<int>() < 0 || diff.get<int>() > 255)
        fail(where + ".maxChannelDiff", "expected an integer in 0..255");
    if (!share.is_number() || share.get<double>() < 0.0 || share.get<double>() > 1.0)
        fail(where + ".maxFailingFraction", "expected a number in 0..1");
    t.tolerance = {diff.get<int>(), share.get<double>()};
    t.reason = entry.value("reason", std::string());
    if (t.reason.empty()) fail(where + ".reason", "every tolerance must say why");
    return t;
}

}  // namespace

std::string GoldenTolerance::describe() const {
    std::ostringstream s;
    s << tolerance.maxChannelDiff << "/255 per channel, " << tolerance.maxFailingFraction * 100.0 << " % of pixels ("
      << (overridden ? "preset's own" : "default") << ": " << reason << ")";
    return s.str();
}

GoldenTolerance toleranceFor(const nlohmann::json& table, std::string_view preset) {
    expectOnly(table, {"default", "presets"}, "table");
    const auto presets = table.value("presets", nlohmann::json::object());
    if (!presets.is_object()) fail("presets", "expected an object");
    for (const auto& [name, entry] : presets.items()) parseEntry(entry, "presets." + name);  // all, not just ours
    if (const auto it = presets.find(std::string(preset)); it != presets.end()) {
        GoldenTolerance t = parseEntry(*it, "presets." + std::string(preset));
        t.overridden = true;
        return t;
    }
    if (!table.contains("default")) fail("table", "missing \"default\"");
    return parseEntry(table["default"], "default");
}

nlohmann::json readToleranceTable(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in) throw std::runtime_error(file.string() + ": cannot read golden tolerances");
    try {
        return nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(file.string() + ": " + e.what());
    }
}

}  // namespace st::test
