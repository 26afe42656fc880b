// libFuzzer target: preset parsing (renderer/settings). Any input must end in a Settings or a
// SettingsError, never a crash, a sanitizer report or another exception; what is accepted must
// survive the round trip Settings -> JSON -> Settings unchanged.
//
//   bytes --nlohmann::json::parse (no exceptions)--> json --fromJson--> Settings s
//   s --toJson--> j2 --fromJson--> s2 == s, toJson(s2) == j2         (in memory)
//   s --toOrderedJson().dump(2)--> text --parse--> fromJson == s     (the text savePresetAtomic writes)
//   bytes --file--> loadPreset: the same outcome as the in-memory path (and its "file:line:col:" code)
#include "renderer/settings/settings_json.h"
#include "tests/fuzz/fuzz_support.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <system_error>

namespace {

namespace fs = std::filesystem;

const std::string kSource = "fuzz.json";

// The file loadPreset reads, in a private folder.
const fs::path& presetFile() {
    static const fs::path file = st::fuzz::makeScratchDir("st-fuzz-preset") / "preset.json";
    return file;
}

// Every message of a SettingsError starts with the source name ("src: path: why" or "src:line:col: ...").
void checkMessages(const st::SettingsError& e, const std::string& source) {
    ST_FUZZ_CHECK(!e.messages().empty());
    for (const std::string& message : e.messages()) ST_FUZZ_CHECK(message.rfind(source + ":", 0) == 0);
}

std::optional<st::Settings> readInMemory(const nlohmann::json& json) {
    try {
        return st::fromJson(json, kSource);
    } catch (const st::SettingsError& e) {
        if (st::fuzz::verbose()) std::fprintf(stderr, "fuzz_preset: SettingsError: %s\n", e.what());
        checkMessages(e, kSource);
        return std::nullopt;
    }
}

void checkRoundTrip(const st::Settings& s) {
    const nlohmann::json j2 = st::toJson(s);
    const st::Settings s2 = st::fromJson(j2, "round trip");  // a valid preset writes a valid preset
    ST_FUZZ_CHECK(s2 == s);
    ST_FUZZ_CHECK(st::toJson(s2) == j2);

    const std::string text = st::toOrderedJson(s).dump(2) + "\n";  // savePresetAtomic's text
    const nlohmann::json reparsed = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    ST_FUZZ_CHECK(!reparsed.is_discarded());
    ST_FUZZ_CHECK(st::fromJson(reparsed, "saved text") == s);
}

// loadPreset on the same bytes: same verdict, same Settings.
void checkFile(const std::uint8_t* data, std::size_t size, const std::optional<st::Settings>& inMemory) {
    const fs::path& file = presetFile();
    {
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
        ST_FUZZ_CHECK(out.good());
    }
    try {
        const st::Settings loaded = st::loadPreset(file);
        ST_FUZZ_CHECK(inMemory.has_value());
        ST_FUZZ_CHECK(loaded == *inMemory);
    } catch (const st::SettingsError& e) {
        if (st::fuzz::verbose() && !inMemory) std::fprintf(stderr, "fuzz_preset: loadPreset: %s\n", e.what());
        ST_FUZZ_CHECK(!inMemory.has_value());
        checkMessages(e, file.string());
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const nlohmann::json json = nlohmann::json::parse(data, data + size, nullptr, /*allow_exceptions=*/false);
    std::optional<st::Settings> settings;
    if (!json.is_discarded()) {
        settings = readInMemory(json);
        if (st::fuzz::verbose() && settings) std::fprintf(stderr, "fuzz_preset: valid preset\n");
        if (settings) checkRoundTrip(*settings);
    }
    checkFile(data, size, settings);
    return 0;
}
