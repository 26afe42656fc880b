// Files, URIs and the GLB container: everything read from disk goes through here.
#include "renderer/scene/gltf_detail.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

namespace st::gltf {

namespace fs = std::filesystem;

void LoadContext::fail(const std::string& what) const {
    throw SceneError(file.string() + ": " + what);
}

void LoadContext::warn(const std::string& what) {
    if (warned.insert(what).second) warnings.push_back(what);
}

void LoadContext::chargeDecoded(std::uint64_t bytes, const std::string& what) {
    if (bytes > limits.maxDecodedBytes || decodedBytes > limits.maxDecodedBytes - bytes) {
        fail(what + " would take the decoded scene above " + std::to_string(limits.maxDecodedBytes) +
             " bytes (GltfLimits::maxDecodedBytes)");
    }
    decodedBytes += bytes;
}

std::vector<std::uint8_t> readFileChecked(LoadContext& ctx, const fs::path& path,
                                          const std::string& what) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) ctx.fail(what + " not found");
    if (!fs::is_regular_file(status)) ctx.fail(what + " is not a regular file");
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) ctx.fail(what + " cannot be read: " + ec.message());
    if (size > ctx.limits.maxFileBytes) {
        ctx.fail(what + " is " + std::to_string(size) + " bytes, above the limit of " +
                 std::to_string(ctx.limits.maxFileBytes) + " (GltfLimits::maxFileBytes)");
    }
    if (ctx.fileBytesRead + size > ctx.limits.maxTotalFileBytes) {
        ctx.fail(what + " would take the files read above " +
                 std::to_string(ctx.limits.maxTotalFileBytes) + " bytes (GltfLimits::maxTotalFileBytes)");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) ctx.fail(what + " cannot be opened: " + std::strerror(errno));
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
    in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size));
    if (static_cast<std::uintmax_t>(in.gcount()) != size) ctx.fail(what + " could not be read completely");
    ctx.fileBytesRead += size;
    return bytes;
}

namespace {

unsigned char hexValue(char c) {  // tinygltf's dlib::from_hex: anything else is 0
    if (c >= '0' && c <= '9') return static_cast<unsigned char>(c - '0');
    if (c >= 'a' && c <= 'f') return static_cast<unsigned char>(c - 'a' + 10);
    if (c >= 'A' && c <= 'F') return static_cast<unsigned char>(c - 'A' + 10);
    return 0;
}

std::optional<std::string> schemeRefusal(const std::string& decoded) {
    const std::size_t colon = decoded.find(':');
    const std::size_t slash = decoded.find('/');
    if (colon == std::string::npos || (slash != std::string::npos && slash < colon)) return std::nullopt;
    std::string scheme = decoded.substr(0, colon);
    std::transform(scheme.begin(), scheme.end(), scheme.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (scheme.size() == 1) return std::string("is an absolute path (drive letter)");
    if (scheme == "file") return std::string("is an absolute file: URI");
    return "uses the scheme '" + scheme + ":'";
}

std::uint32_t readU32(const std::vector<std::uint8_t>& bytes, std::size_t offset) {
    std::uint32_t v = 0;
    std::memcpy(&v, bytes.data() + offset, 4);  // GLB is little-endian, like every target here
    return v;
}

}  // namespace

std::string decodeUri(const std::string& uri) {
    std::string out;
    out.reserve(uri.size());
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '+') {
            out += ' ';
        } else if (uri[i] == '%' && uri.size() > i + 2) {
            out += static_cast<char>((hexValue(uri[i + 1]) << 4) | hexValue(uri[i + 2]));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

bool isDataUri(std::string_view uri) { return uri.substr(0, 5) == "data:"; }

bool insideSceneDir(const LoadContext& ctx, const fs::path& path) {
    std::error_code ec;
    const fs::path resolved = fs::weakly_canonical(path, ec);
    if (ec) return false;
    auto [dirIt, pathIt] = std::mismatch(ctx.sceneDir.begin(), ctx.sceneDir.end(), resolved.begin(),
                                         resolved.end());
    return dirIt == ctx.sceneDir.end() && pathIt != resolved.end();
}

std::optional<std::string> uriRefusal(const LoadContext& ctx, const std::string& uri) {
    if (isDataUri(uri)) return std::nullopt;
    const std::string decoded = decodeUri(uri);
    if (decoded.empty()) return std::string("is empty");
    if (decoded.find('\0') != std::string::npos) return std::string("contains a NUL character");
    if (decoded.front() == '/' || decoded.front() == '\\') return std::string("is an absolute path");
    if (auto refusal = schemeRefusal(decoded)) return refusal;
    const fs::path relative = fs::path(decoded).lexically_normal();
    if (relative.empty() || *relative.begin() == "..") return std::string("escapes the scene folder");
    if (!insideSceneDir(ctx, ctx.sceneDir / relative)) {
        return std::string("resolves outside the scene folder (through a symbolic link)");
    }
    return std::nullopt;
}

int jsonNestingDepth(std::string_view json) {
    int depth = 0;
    int deepest = 0;
    bool inString = false;
    bool escaped = false;
    for (char c : json) {
        if (inString) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return deepest;
}

GlbChunks splitGlb(const LoadContext& ctx, const std::vector<std::uint8_t>& bytes) {
    const std::size_t size = bytes.size();
    if (size < 20) ctx.fail("is too short for a GLB (" + std::to_string(size) + " bytes)");
    if (readU32(bytes, 4) != 2) ctx.fail("is GLB version " + std::to_string(readU32(bytes, 4)) + "; only 2 is read");
    GlbChunks glb;
    glb.glbLength = readU32(bytes, 8);
    // Checked first: every remaining-length below subtracts the 20-byte header from it.
    if (glb.glbLength < 20) {
        ctx.fail("GLB header declares " + std::to_string(glb.glbLength) + " bytes, less than its own 20-byte header");
    }
    if (glb.glbLength > size) {
        ctx.fail("GLB header declares " + std::to_string(glb.glbLength) + " bytes but the file has only " +
                 std::to_string(size) + " (truncated)");
    }
    const std::size_t jsonLength = readU32(bytes, 12);
    if (readU32(bytes, 16) != 0x4E4F534Au) ctx.fail("GLB first chunk is not JSON");
    if (jsonLength == 0 || jsonLength > glb.glbLength - 20) {
        ctx.fail("GLB JSON chunk declares " + std::to_string(jsonLength) + " bytes but " +
                 std::to_string(glb.glbLength - 20) + " remain (truncated)");
    }
    glb.json = std::string_view(reinterpret_cast<const char*>(bytes.data()) + 20, jsonLength);
    const std::size_t binHeader = 20 + jsonLength;
    if (binHeader == glb.glbLength) return glb;
    if (glb.glbLength - binHeader < 8) ctx.fail("GLB ends inside the BIN chunk header (truncated)");
    glb.binSize = readU32(bytes, binHeader);
    if (readU32(bytes, binHeader + 4) != 0x004E4942u) ctx.fail("GLB second chunk is not BIN");
    if (glb.binSize > glb.glbLength - binHeader - 8) {
        ctx.fail("GLB BIN chunk declares " + std::to_string(glb.binSize) + " bytes but " +
                 std::to_string(glb.glbLength - binHeader - 8) + " remain (truncated)");
    }
    if (glb.binSize < 4 || glb.binSize % 4 != 0) {
        ctx.fail("GLB BIN chunk length " + std::to_string(glb.binSize) + " is not a positive multiple of 4");
    }
    glb.hasBin = true;
    return glb;
}

}  // namespace st::gltf
