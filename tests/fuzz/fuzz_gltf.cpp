// libFuzzer target: glTF loading (renderer/scene/gltf_*.cpp) of hostile files. The input is
// written as scene.glb (when it starts with the GLB magic "glTF") or scene.gltf into a private
// folder and loaded with small GltfLimits. The only acceptable failure is a SceneError naming the
// file; anything else (another exception, a crash, a sanitizer report, an allocation above
// -malloc_limit_mb, a timeout) is a bug. A successful load must give a Scene the renderer can use
// as is (the invariants in checkScene).
//
// The folder also holds fixed files the corpus refers to, so mutations reach external-file code:
//   a.bin            the corpus triangle buffer (layout in makeTriangleBuffer; 104 bytes)
//   a.png            a 2x2 RGBA PNG
//   sub/a.bin        the same buffer one folder down
//   escape.bin       a symlink to ../outside.bin, outside the scene folder: must be refused
// (tests/fuzz/make_gltf_corpus.py writes the seeds with the same layout.)
#include "renderer/scene/gltf_scene.h"
#include "tests/fuzz/fuzz_support.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

namespace {

namespace fs = std::filesystem;

// Small: a 16 KiB input easily declares more than these (so the limit checks run), and what is
// accepted stays cheap to check. Large enough for every seed.
st::GltfLimits fuzzLimits() {
    st::GltfLimits limits;
    limits.maxFileBytes = 1u << 20;
    limits.maxTotalFileBytes = 4u << 20;
    limits.maxJsonBytes = 1u << 20;
    limits.maxJsonDepth = 64;
    limits.maxVertices = 100'000;
    limits.maxIndices = 300'000;
    limits.maxDecodedBytes = 32u << 20;
    limits.maxImageDimension = 1024;
    limits.maxNodeInstances = 10'000;
    limits.maxNodeDepth = 64;
    return limits;
}

// Positions (0,0,0) (1,0,0) (0,1,0) at 0, normals (0,0,1) at 36, uvs at 72, u16 indices 0 1 2 at
// 96 (padded to 104).
std::vector<std::uint8_t> makeTriangleBuffer() {
    const float floats[] = {0, 0, 0, 1, 0, 0, 0, 1, 0,   0, 0, 1, 0, 0, 1, 0, 0, 1,   0, 0, 1, 0, 0, 1};
    const std::uint16_t indices[] = {0, 1, 2, 0};
    std::vector<std::uint8_t> out(sizeof floats + sizeof indices);
    std::memcpy(out.data(), floats, sizeof floats);
    std::memcpy(out.data() + sizeof floats, indices, sizeof indices);
    return out;
}

const std::uint8_t kPng2x2[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00,
    0x00, 0x02, 0x00, 0x00, 0x00, 0x02, 0x08, 0x06, 0x00, 0x00, 0x00, 0x72, 0xb6, 0x0d, 0x24, 0x00, 0x00, 0x00,
    0x15, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0xf8, 0xcf, 0xc0, 0xf0, 0x1f, 0x08, 0x1b, 0x18, 0x80, 0x34,
    0x08, 0x30, 0x00, 0x00, 0x43, 0xd3, 0x08, 0x79, 0x78, 0xce, 0x21, 0xcc, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45,
    0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};

void writeFile(const fs::path& file, const void* data, std::size_t size) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
    ST_FUZZ_CHECK(out.good());
}

struct Workspace {
    fs::path root;      // scratch folder, removed at exit
    fs::path sceneDir;  // root/scene
};

const Workspace& workspace() {
    static const Workspace ws = [] {
        const fs::path root = st::fuzz::makeScratchDir("st-fuzz-gltf");
        Workspace w{root, root / "scene"};
        fs::create_directories(w.sceneDir / "sub");
        const std::vector<std::uint8_t> buffer = makeTriangleBuffer();
        writeFile(w.sceneDir / "a.bin", buffer.data(), buffer.size());
        writeFile(w.sceneDir / "sub" / "a.bin", buffer.data(), buffer.size());
        writeFile(w.sceneDir / "a.png", kPng2x2, sizeof kPng2x2);
        writeFile(w.root / "outside.bin", buffer.data(), buffer.size());
        fs::create_symlink("../outside.bin", w.sceneDir / "escape.bin");
        return w;
    }();
    return ws;
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// What the renderer and the ray caster rely on without checking.
void checkScene(const st::Scene& scene, const st::GltfLimits& limits) {
    ST_FUZZ_CHECK(!scene.draws.empty());
    ST_FUZZ_CHECK(scene.vertices.size() <= limits.maxVertices);
    ST_FUZZ_CHECK(scene.indices.size() <= limits.maxIndices);
    ST_FUZZ_CHECK(scene.indices.size() % 3 == 0);
    for (const std::uint32_t index : scene.indices) ST_FUZZ_CHECK(index < scene.vertices.size());
    for (const st::Vertex& v : scene.vertices) {
        ST_FUZZ_CHECK(finite(v.position));
        ST_FUZZ_CHECK(finite(v.normal));
        ST_FUZZ_CHECK(std::isfinite(v.uv.x) && std::isfinite(v.uv.y));
    }
    for (const st::DrawItem& d : scene.draws) {
        ST_FUZZ_CHECK(d.indexCount > 0 && d.indexCount % 3 == 0);
        ST_FUZZ_CHECK(std::uint64_t(d.firstIndex) + d.indexCount <= scene.indices.size());
        ST_FUZZ_CHECK(d.material >= 0 && std::size_t(d.material) < scene.materials.size());
        ST_FUZZ_CHECK(finite(d.wsBounds.min) && finite(d.wsBounds.max));
    }
    for (const st::Material& m : scene.materials) {
        ST_FUZZ_CHECK(m.baseColorTexture >= -1 && m.baseColorTexture < static_cast<int>(scene.images.size()));
    }
    for (const st::Image& image : scene.images) {
        ST_FUZZ_CHECK(image.width >= 1 && image.width <= limits.maxImageDimension);
        ST_FUZZ_CHECK(image.height >= 1 && image.height <= limits.maxImageDimension);
        ST_FUZZ_CHECK(image.rgba.size() == std::size_t(image.width) * std::size_t(image.height) * 4);
    }
    ST_FUZZ_CHECK(finite(scene.wsBounds.min) && finite(scene.wsBounds.max));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const Workspace& ws = workspace();
    const bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    const fs::path file = ws.sceneDir / (glb ? "scene.glb" : "scene.gltf");
    std::error_code ec;
    fs::remove(ws.sceneDir / (glb ? "scene.gltf" : "scene.glb"), ec);
    writeFile(file, data, size);

    const st::GltfLimits limits = fuzzLimits();
    try {
        const st::GltfLoadResult result = st::loadGltf(file, limits);
        checkScene(result.scene, limits);
        if (st::fuzz::verbose()) {
            std::fprintf(stderr, "fuzz_gltf: loaded: %zu triangles, %zu draws, %zu images, %zu warnings\n",
                         result.scene.triangleCount(), result.scene.draws.size(), result.scene.images.size(),
                         result.warnings.size());
            for (const std::string& w : result.warnings) std::fprintf(stderr, "fuzz_gltf:   warning: %s\n", w.c_str());
        }
    } catch (const st::SceneError& e) {
        if (st::fuzz::verbose()) std::fprintf(stderr, "fuzz_gltf: SceneError: %s\n", e.what());
        ST_FUZZ_CHECK(std::string(e.what()).rfind(file.string() + ": ", 0) == 0);  // names the file
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz_gltf: an exception other than SceneError escaped loadGltf: %s\n", e.what());
        std::abort();
    }
    return 0;
}
