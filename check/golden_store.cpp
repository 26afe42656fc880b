#include "check/golden_store.h"

#include <cctype>
#include <fstream>
#include <stdexcept>

namespace st::check {
namespace fs = std::filesystem;
using OJson = nlohmann::ordered_json;

namespace {
OJson readJson(const fs::path& file) {
    std::ifstream in(file);
    if (!in) throw std::runtime_error(file.string() + ": cannot open");
    try {
        return OJson::parse(in);
    } catch (const OJson::exception& e) {
        throw std::runtime_error(file.string() + ": not valid JSON: " + e.what());
    }
}

std::string textAt(const OJson& j, const char* key, const fs::path& file) {
    if (!j.contains(key) || !j[key].is_string()) throw std::runtime_error(file.string() + ": /" + key + ": expected a string");
    return j[key].get<std::string>();
}

int intAt(const OJson& j, const char* key, const fs::path& file) {
    if (!j.contains(key) || !j[key].is_number_integer()) throw std::runtime_error(file.string() + ": /" + key + ": expected an integer");
    return j[key].get<int>();
}
}  // namespace

std::string rendererSlug(const std::string& renderer) {
    std::string out;
    for (char c : renderer) {
        if (std::isalnum(static_cast<unsigned char>(c))) out += char(std::tolower(static_cast<unsigned char>(c)));
        else if (!out.empty() && out.back() != '-') out += '-';
    }
    while (!out.empty() && out.back() == '-') out.pop_back();
    return out.empty() ? "unknown-renderer" : out;
}

fs::path goldenDir(const fs::path& root, const std::string& renderer, const std::string& name) {
    const fs::path perRenderer = root / rendererSlug(renderer);
    return fs::is_directory(perRenderer) ? perRenderer / name : root / name;
}

OJson metaJson(const GoldenMeta& m) {
    return OJson{{"renderer", m.renderer}, {"version", m.version},     {"commit", m.commit},
                 {"settingsHash", m.settingsHash}, {"width", m.width}, {"height", m.height}};
}

std::optional<Golden> readGolden(const fs::path& dir) {
    if (!fs::exists(dir / "image.png")) return std::nullopt;
    Golden g;
    g.dir = dir;
    g.image = readImage(dir / "image.png");
    g.figures = readJson(dir / "figures.json");
    const fs::path metaFile = dir / "meta.json";
    const OJson meta = readJson(metaFile);
    g.meta = {textAt(meta, "renderer", metaFile), textAt(meta, "version", metaFile), textAt(meta, "commit", metaFile),
              textAt(meta, "settingsHash", metaFile), intAt(meta, "width", metaFile), intAt(meta, "height", metaFile)};
    return g;
}

void writeGolden(const Golden& g) {
    std::error_code ec;
    fs::create_directories(g.dir, ec);
    if (ec || !fs::is_directory(g.dir))
        throw std::runtime_error(g.dir.string() + ": cannot create the golden folder: " + (ec ? ec.message() : "not a folder"));
    writeImageAtomic(g.dir / "image.png", g.image);
    writeTextAtomic(g.dir / "figures.json", g.figures.dump(2) + "\n");
    writeTextAtomic(g.dir / "meta.json", metaJson(g.meta).dump(2) + "\n");
}

}  // namespace st::check
