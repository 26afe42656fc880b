// Checks on the raw glTF JSON before tinygltf touches a buffer or an image (see gltf_detail.h).
#include "renderer/scene/gltf_detail.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cctype>
#include <cmath>
#include <system_error>

namespace st::gltf {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// The data: prefixes tinygltf 2.7.0 decodes (DecodeDataURI), for buffers and images alike.
constexpr std::array<std::string_view, 7> kDataPrefixes = {
    "data:application/octet-stream;base64,", "data:image/jpeg;base64,", "data:image/png;base64,",
    "data:image/bmp;base64,", "data:image/gif;base64,", "data:text/plain;base64,",
    "data:application/gltf-buffer;base64,"};
// Decodes to three zero bytes: tinygltf accepts it, stb_image then refuses it.
constexpr const char* kStubImageUri = "data:image/png;base64,AAAA";

std::string shortUri(const std::string& uri) {
    return "'" + (uri.size() <= 80 ? uri : uri.substr(0, 77) + "...") + "'";
}

// Bytes tinygltf's base64_decode yields: it stops at the first non-base64 character or '='.
std::optional<std::uint64_t> dataUriSize(const std::string& uri) {
    for (std::string_view prefix : kDataPrefixes) {
        if (uri.compare(0, prefix.size(), prefix) != 0) continue;
        std::size_t k = prefix.size();
        while (k < uri.size() &&
               (std::isalnum(static_cast<unsigned char>(uri[k])) || uri[k] == '+' || uri[k] == '/')) {
            ++k;
        }
        const std::uint64_t chars = k - prefix.size();
        const std::uint64_t size = chars / 4 * 3 + (chars % 4 > 1 ? chars % 4 - 1 : 0);
        if (size > 0) return size;
    }
    return std::nullopt;
}

std::uint64_t unsignedMember(const LoadContext& ctx, const Json& object, const char* key,
                             const std::string& what, std::optional<std::uint64_t> fallback) {
    const auto it = object.find(key);
    if (it == object.end()) {
        if (!fallback) ctx.fail(what + " has no '" + key + "'");
        return *fallback;
    }
    if (it->is_number_unsigned()) return it->get<std::uint64_t>();
    if (it->is_number_float()) {
        const double v = it->get<double>();
        if (v >= 0.0 && v < 9.0e15 && std::floor(v) == v) return static_cast<std::uint64_t>(v);
    }
    ctx.fail(what + " '" + key + "' is not a non-negative integer");
}

const Json* arrayMember(const LoadContext& ctx, const Json& doc, const char* key) {
    const auto it = doc.find(key);
    if (it == doc.end()) return nullptr;
    if (!it->is_array()) ctx.fail("'" + std::string(key) + "' is not an array");
    for (const Json& element : *it) {
        if (!element.is_object()) ctx.fail("'" + std::string(key) + "' holds something that is not an object");
    }
    return &*it;
}

std::string uriMember(const LoadContext& ctx, const Json& object, const std::string& what) {
    const auto it = object.find("uri");
    if (it == object.end()) return {};
    if (!it->is_string()) ctx.fail(what + " 'uri' is not a string");
    return it->get<std::string>();
}

void checkExternalBuffer(const LoadContext& ctx, const std::string& uri, std::uint64_t byteLength,
                         const std::string& what) {
    if (auto why = uriRefusal(ctx, uri)) {
        ctx.fail(what + " URI " + shortUri(uri) + " " + *why + "; only files inside " +
                 ctx.sceneDir.string() + " are read");
    }
    const std::string name = "'" + decodeUri(uri) + "'";
    std::error_code ec;
    const fs::path path = ctx.sceneDir / decodeUri(uri);
    if (!fs::is_regular_file(path, ec)) ctx.fail(what + " file " + name + " not found");
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) ctx.fail(what + " file " + name + " cannot be read: " + ec.message());
    if (size < byteLength) {
        ctx.fail(what + " declares byteLength " + std::to_string(byteLength) + " but file " + name +
                 " has only " + std::to_string(size) + " bytes (truncated)");
    }
    if (size > byteLength) {
        ctx.fail(what + " declares byteLength " + std::to_string(byteLength) + " but file " + name +
                 " has " + std::to_string(size) + " bytes; tinygltf needs them equal");
    }
}

void checkEmbeddedBuffer(const LoadContext& ctx, std::uint64_t byteLength, const GlbChunks* glb,
                         const std::string& what) {
    if (glb == nullptr) ctx.fail(what + " has no uri; only a .glb can embed its buffer");
    if (!glb->hasBin) ctx.fail(what + " has no uri but the GLB has no BIN chunk");
    if (byteLength > glb->binSize) {
        ctx.fail(what + " declares byteLength " + std::to_string(byteLength) +
                 " but the GLB BIN chunk holds only " + std::to_string(glb->binSize) + " bytes");
    }
}

std::vector<std::uint64_t> checkBuffers(const LoadContext& ctx, const Json& doc, const GlbChunks* glb) {
    std::vector<std::uint64_t> lengths;
    const Json* buffers = arrayMember(ctx, doc, "buffers");
    if (buffers == nullptr) return lengths;
    for (const Json& buffer : *buffers) {
        const std::string what = "buffer " + std::to_string(lengths.size());
        const std::uint64_t byteLength = unsignedMember(ctx, buffer, "byteLength", what, std::nullopt);
        if (byteLength == 0) ctx.fail(what + " has byteLength 0");
        if (byteLength > ctx.limits.maxFileBytes) {
            ctx.fail(what + " declares byteLength " + std::to_string(byteLength) + ", above the limit of " +
                     std::to_string(ctx.limits.maxFileBytes) + " (GltfLimits::maxFileBytes)");
        }
        const std::string uri = uriMember(ctx, buffer, what);
        if (uri.empty()) {
            checkEmbeddedBuffer(ctx, byteLength, glb, what);
        } else if (isDataUri(uri)) {
            const std::optional<std::uint64_t> size = dataUriSize(uri);
            if (!size) ctx.fail(what + " has a data: URI that tinygltf cannot decode (base64 only)");
            if (*size != byteLength) {
                ctx.fail(what + " declares byteLength " + std::to_string(byteLength) +
                         " but its data: URI holds " + std::to_string(*size) + " bytes");
            }
        } else {
            checkExternalBuffer(ctx, uri, byteLength, what);
        }
        lengths.push_back(byteLength);
    }
    return lengths;
}

void checkBufferViews(const LoadContext& ctx, const Json& doc, const std::vector<std::uint64_t>& lengths) {
    const Json* views = arrayMember(ctx, doc, "bufferViews");
    if (views == nullptr) return;
    std::size_t index = 0;
    for (const Json& view : *views) {
        const std::string what = "buffer view " + std::to_string(index++);
        const std::uint64_t buffer = unsignedMember(ctx, view, "buffer", what, std::nullopt);
        if (buffer >= lengths.size()) {
            ctx.fail(what + " refers to buffer " + std::to_string(buffer) + ", but the file has " +
                     std::to_string(lengths.size()) + " buffers");
        }
        const std::uint64_t offset = unsignedMember(ctx, view, "byteOffset", what, 0);
        const std::uint64_t length = unsignedMember(ctx, view, "byteLength", what, std::nullopt);
        if (length == 0) ctx.fail(what + " has byteLength 0");
        if (offset > lengths[buffer] || length > lengths[buffer] - offset) {
            ctx.fail(what + " (byteOffset " + std::to_string(offset) + ", byteLength " + std::to_string(length) +
                     ") overruns buffer " + std::to_string(buffer) + " (" + std::to_string(lengths[buffer]) +
                     " bytes)");
        }
    }
}

void checkAsset(const LoadContext& ctx, const Json& doc) {
    const auto asset = doc.find("asset");
    if (asset == doc.end() || !asset->is_object()) ctx.fail("is not glTF: it has no 'asset' object");
    const auto version = asset->find("version");
    if (version == asset->end() || !version->is_string()) ctx.fail("is not glTF: 'asset' has no 'version' string");
    const std::string v = version->get<std::string>();
    if (v.rfind("2.", 0) != 0) ctx.fail("is glTF version '" + v.substr(0, 20) + "'; only 2.x is read");
}

// Returns whether the JSON was edited (a data: image tinygltf would fail on was stubbed).
bool checkImages(LoadContext& ctx, Json& doc) {
    if (arrayMember(ctx, doc, "images") == nullptr) return false;
    bool edited = false;
    int index = 0;
    for (Json& image : doc["images"]) {
        const std::string what = "image " + std::to_string(index);
        const std::string uri = uriMember(ctx, image, what);
        if (uri.empty()) {
            // in a buffer view: checked with the buffer views
        } else if (!isDataUri(uri)) {
            if (auto why = uriRefusal(ctx, uri)) {
                ctx.fail(what + " URI " + shortUri(uri) + " " + *why + "; only files inside " +
                         ctx.sceneDir.string() + " are read");
            }
        } else if (!dataUriSize(uri)) {
            ctx.unreadableImages[index] = "its data: URI is not base64 PNG or JPEG";
            image["uri"] = kStubImageUri;
            edited = true;
        }
        ++index;
    }
    return edited;
}

}  // namespace

std::optional<std::string> prevalidateJson(LoadContext& ctx, std::string_view text, const GlbChunks* glb) {
    if (text.size() > ctx.limits.maxJsonBytes) {
        ctx.fail("JSON is " + std::to_string(text.size()) + " bytes, above the limit of " +
                 std::to_string(ctx.limits.maxJsonBytes) + " (GltfLimits::maxJsonBytes)");
    }
    const int depth = jsonNestingDepth(text);
    if (depth > ctx.limits.maxJsonDepth) {
        ctx.fail("JSON is nested " + std::to_string(depth) + " levels deep, above the limit of " +
                 std::to_string(ctx.limits.maxJsonDepth) + " (GltfLimits::maxJsonDepth)");
    }
    Json doc;
    try {
        doc = Json::parse(text.begin(), text.end());
    } catch (const Json::exception& e) {
        ctx.fail(std::string("is not valid JSON: ") + e.what());
    }
    if (!doc.is_object()) ctx.fail("is not glTF: the JSON top level is not an object");
    checkAsset(ctx, doc);
    checkBufferViews(ctx, doc, checkBuffers(ctx, doc, glb));
    if (!checkImages(ctx, doc)) return std::nullopt;
    return doc.dump();
}

}  // namespace st::gltf
