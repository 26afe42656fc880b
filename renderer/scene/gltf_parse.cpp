// tinygltf, fenced in: the main file is read and checked here, tinygltf only parses, every file it
// opens goes through callbacks that apply the folder rule and the size limits, and images are
// kept encoded (decoded later, only where a material uses them).
#include "renderer/scene/gltf_detail.h"

#include <cstring>
#include <sstream>
#include <system_error>

namespace st::gltf {

namespace {

namespace fs = std::filesystem;

LoadContext& contextOf(void* user) { return *static_cast<LoadContext*>(user); }

bool fsFileExists(const std::string& path, void* user) {
    std::error_code ec;
    return insideSceneDir(contextOf(user), path) && fs::is_regular_file(path, ec);
}

std::string fsExpandFilePath(const std::string& path, void*) { return path; }  // no ~ or $VAR

bool fsReadWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    LoadContext& ctx = contextOf(user);
    try {
        const std::string name = "file '" + fs::path(path).lexically_relative(ctx.sceneDir).string() + "'";
        if (!insideSceneDir(ctx, path)) ctx.fail("refused to read " + path + ": outside the scene folder");
        *out = readFileChecked(ctx, path, name);
        return true;
    } catch (const SceneError& e) {
        if (ctx.fsRefusal.empty()) ctx.fsRefusal = e.what();
        if (err != nullptr) *err += e.what();
        return false;
    }
}

bool fsWriteWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err != nullptr) *err += "writing is disabled";
    return false;
}

void appendU32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    const auto* p = reinterpret_cast<const std::uint8_t*>(&v);
    out.insert(out.end(), p, p + 4);
}

// The same GLB with another JSON chunk (padded with spaces) and the original BIN chunk.
std::vector<std::uint8_t> rebuildGlb(const std::vector<std::uint8_t>& glb, const GlbChunks& chunks, std::string json) {
    json.resize((json.size() + 3) / 4 * 4, ' ');
    const std::size_t binStart = 20 + chunks.json.size();
    const std::size_t binBytes = chunks.hasBin ? 8 + chunks.binSize : 0;
    std::vector<std::uint8_t> out(glb.begin(), glb.begin() + 8);
    appendU32(out, static_cast<std::uint32_t>(20 + json.size() + binBytes));
    appendU32(out, static_cast<std::uint32_t>(json.size()));
    appendU32(out, 0x4E4F534Au);
    out.insert(out.end(), json.begin(), json.end());
    const auto bin = glb.begin() + static_cast<std::ptrdiff_t>(binStart);
    out.insert(out.end(), bin, bin + static_cast<std::ptrdiff_t>(binBytes));
    return out;
}

std::string firstLines(const std::string& text, std::size_t maxChars = 400) {
    std::string out = text.substr(0, maxChars);
    while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
    for (char& c : out) {
        if (c == '\n') c = ';';
    }
    return text.size() > maxChars ? out + "..." : out;
}

// tinygltf's own warnings, except those about images: decodeImage reports those.
void forwardWarnings(LoadContext& ctx, const std::string& warn) {
    std::istringstream lines(warn);
    for (std::string line; std::getline(lines, line);) {
        if (line.empty() || line.find("image") != std::string::npos || line.find("File not found") == 0) continue;
        ctx.warn("tinygltf: " + firstLines(line));
    }
}

bool runTinygltf(LoadContext& ctx, tinygltf::TinyGLTF& loader, std::vector<std::uint8_t>& bytes, tinygltf::Model& model,
                 std::string& err, std::string& warn) {
    const std::string baseDir = ctx.sceneDir.string();
    if (bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0) {
        const GlbChunks chunks = splitGlb(ctx, bytes);
        std::size_t length = chunks.glbLength;
        if (auto edited = prevalidateJson(ctx, chunks.json, &chunks)) {
            bytes = rebuildGlb(bytes, chunks, std::move(*edited));
            length = bytes.size();
        }
        return loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), static_cast<unsigned>(length), baseDir);
    }
    std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    const std::optional<std::string> edited = prevalidateJson(ctx, text, nullptr);
    if (edited) text = *edited;
    return loader.LoadASCIIFromString(&model, &err, &warn, text.data(), static_cast<unsigned>(text.size()), baseDir);
}

}  // namespace

tinygltf::Model parseModel(LoadContext& ctx) {
    std::vector<std::uint8_t> bytes = readFileChecked(ctx, ctx.file, "scene file");
    if (bytes.empty()) ctx.fail("is empty");
    if (bytes.size() > 0xFFFFFFF0u) ctx.fail("is too large for tinygltf (4 GiB)");
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({&fsFileExists, &fsExpandFilePath, &fsReadWholeFile, &fsWriteWholeFile, &ctx});
    loader.SetImageLoader(&keepEncodedImage, &ctx);
    tinygltf::Model model;
    std::string err;
    std::string warn;
    bool ok = false;
    try {
        ok = runTinygltf(ctx, loader, bytes, model, err, warn);
    } catch (const SceneError&) {
        throw;
    } catch (const std::exception& e) {
        ctx.fail(std::string("tinygltf failed: ") + e.what());
    }
    if (!ctx.fsRefusal.empty()) throw SceneError(ctx.fsRefusal);
    if (!ok) ctx.fail("is not valid glTF: " + firstLines(err.empty() ? warn : err));
    forwardWarnings(ctx, warn);
    if (!err.empty()) ctx.warn("tinygltf: " + firstLines(err));
    return model;
}

}  // namespace st::gltf
