#include "app/editor/layout_file.h"

#include "renderer/image/image_io.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>

namespace st::app {

ui::LayoutPrefs loadLayoutPrefs(const std::filesystem::path& file) {
    ui::LayoutPrefs p;
    std::ifstream in(file);
    if (!in) return p;
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (!j.is_object()) return p;
    auto number = [&j](const char* key, float fallback) {
        const auto it = j.find(key);
        return it != j.end() && it->is_number() ? it->get<float>() : fallback;
    };
    p.leftWidth = number("leftWidth", p.leftWidth);
    p.rightWidth = number("rightWidth", p.rightWidth);
    p.bottomHeight = number("bottomHeight", p.bottomHeight);
    if (const auto it = j.find("panelsHidden"); it != j.end() && it->is_boolean()) p.panelsHidden = it->get<bool>();
    return p;
}

void saveLayoutPrefs(const std::filesystem::path& file, const ui::LayoutPrefs& p) {
    const nlohmann::json j{{"leftWidth", p.leftWidth}, {"rightWidth", p.rightWidth},
                           {"bottomHeight", p.bottomHeight}, {"panelsHidden", p.panelsHidden}};
    try {
        std::error_code ec;
        std::filesystem::create_directories(file.parent_path(), ec);
        writeTextAtomic(file, j.dump(2) + "\n");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "warning: could not keep the panel layout: %s\n", e.what());
    }
}

void writeLayoutReport(const std::filesystem::path& file, const ui::ItemRects& rects, ImVec2 display,
                       ImVec2 scenePos, ImVec2 sceneSize) {
    auto box = [](ImVec2 pos, ImVec2 size) { return nlohmann::json::array({pos.x, pos.y, size.x, size.y}); };
    nlohmann::json j{{"display", {display.x, display.y}}, {"scene", box(scenePos, sceneSize)}};
    j["windows"] = nlohmann::json::object();
    for (const auto& [key, r] : rects)
        if (key.rfind("window.", 0) == 0) j["windows"][key.substr(7)] = box(r.min, {r.max.x - r.min.x, r.max.y - r.min.y});
        else j["items"][key] = box(r.min, {r.max.x - r.min.x, r.max.y - r.min.y});  // where a script clicks
    writeTextAtomic(file, j.dump(2) + "\n");
    std::printf("wrote %s\n", file.string().c_str());
}

}  // namespace st::app
