#pragma once
// The golden folder of a check suite. Per preset, GOLDEN/<name>/ holds
//   image.png     the rendered frame,
//   figures.json  its figures, exactly as `measure` writes metrics.json,
//   meta.json     the renderer string, product version, commit and a hash of the settings.
// Goldens per renderer are allowed: GOLDEN/<renderer-slug>/<name>/ is preferred where it exists.
// Writes are atomic per file (tmp + rename), meta.json last. No GL.
#include "renderer/image/image_io.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>

namespace st::check {

struct GoldenMeta {
    std::string renderer;      // GL_RENDERER of the machine that made it
    std::string version;       // the product version ("0.1")
    std::string commit;        // the commit the binary was built from
    std::string settingsHash;  // of the settings replayed (size overrides included)
    int width = 0, height = 0;
};

struct Golden {
    std::filesystem::path dir;
    GoldenMeta meta;
    Rgba8Image image;
    nlohmann::ordered_json figures;
};

// "llvmpipe (LLVM 15.0.6, 256 bits)" -> "llvmpipe-llvm-15-0-6-256-bits"; "unknown-renderer" if empty.
std::string rendererSlug(const std::string& renderer);

// Where `name`'s golden is read from and written to: ROOT/<slug>/<name> when the folder
// ROOT/<slug> exists, else ROOT/<name>.
std::filesystem::path goldenDir(const std::filesystem::path& root, const std::string& renderer, const std::string& name);

// The golden in `dir`, or nothing when it has no image.png. Throws std::runtime_error naming the
// file and the reason for a golden that is there but unreadable.
std::optional<Golden> readGolden(const std::filesystem::path& dir);
void writeGolden(const Golden& g);  // into g.dir, created if needed; throws std::runtime_error

nlohmann::ordered_json metaJson(const GoldenMeta& m);

}  // namespace st::check
