// Preset files: reading with JSON errors at line:column, and atomic writing (temp file + rename).
#include "renderer/settings/settings_json.h"
#include "renderer/settings/validation.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

namespace fs = std::filesystem;

namespace st {
namespace {

// "file:line:col: " for the byte at `offset` (0-based) of `text`; offset == size means end of text.
std::string locate(const std::string& file, const std::string& text, std::size_t offset) {
    offset = std::min(offset, text.size());
    const auto begin = text.begin();
    const auto line = 1 + std::count(begin, begin + static_cast<std::ptrdiff_t>(offset), '\n');
    const auto lastNewline = offset == 0 ? std::string::npos : text.rfind('\n', offset - 1);
    const std::size_t lineStart = lastNewline == std::string::npos ? 0 : lastNewline + 1;
    const std::size_t column = offset - lineStart + 1;
    return file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": ";
}

// nlohmann's message without its "[json.exception...] parse error at line L, column C: " prefix.
std::string parseReason(const std::string& what) {
    const auto start = what.find("parse error");
    const auto colon = what.find(": ", start == std::string::npos ? 0 : start);
    return colon == std::string::npos ? what : what.substr(colon + 2);
}

// Offset of the byte nlohmann stopped at: its `byte` is 1-based and often one past the token,
// on the line end that finished it; point back at the token's line then.
std::size_t errorOffset(const std::string& text, std::size_t byte) {
    std::size_t offset = byte == 0 ? 0 : byte - 1;
    if (offset > 0 && offset < text.size() && text[offset] == '\n') --offset;
    return offset;
}

// "number overflow parsing '1e999'" carries no position: find the literal in the text.
std::size_t overflowOffset(const std::string& text, const std::string& what) {
    const auto open = what.find('\'');
    const auto close = what.rfind('\'');
    if (open == std::string::npos || close <= open) return text.size();
    const auto at = text.find(what.substr(open + 1, close - open - 1));
    return at == std::string::npos ? text.size() : at;
}

nlohmann::json parseText(const std::string& text, const std::string& file) {
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw SettingsError(locate(file, text, errorOffset(text, e.byte)) + "invalid JSON: " + parseReason(e.what()));
    } catch (const nlohmann::json::out_of_range& e) {
        const std::string what = e.what();
        throw SettingsError(locate(file, text, overflowOffset(text, what)) + "invalid JSON: " +
                            what.substr(what.find(']') + 2));
    }
}

std::string readText(const fs::path& file, const std::string& kind) {
    const std::string name = file.string();
    std::error_code ec;
    const auto status = fs::status(file, ec);
    if (!fs::exists(status)) throw SettingsError(name + ": cannot read " + kind + ": no such file");
    if (fs::is_directory(status)) throw SettingsError(name + ": cannot read " + kind + ": is a directory, not a JSON file");
    // Presets are a few kilobytes; refusing huge files keeps a mistaken path from filling memory.
    constexpr std::uintmax_t kMaxPresetBytes = 16u << 20;
    if (const auto size = fs::file_size(file, ec); !ec && size > kMaxPresetBytes) {
        throw SettingsError(name + ": cannot read " + kind + ": " + std::to_string(size) + " bytes, more than the " +
                            std::to_string(kMaxPresetBytes >> 20) + " MiB a " + kind + " may have");
    }
    std::ifstream in(file, std::ios::binary);
    if (!in) throw SettingsError(name + ": cannot read " + kind + ": " + std::strerror(errno));
    std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad()) throw SettingsError(name + ": cannot read " + kind + ": read error");
    return text;
}

// Writes all of `text` to `file` and flushes it to disk; "" on success, else the reason (and the
// file is removed again). The reason names no file: `file` is a temporary name the user never chose.
std::string writeSynced(const fs::path& file, const std::string& text) {
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) {
        const int err = errno;
        std::error_code ec;
        if (err == ENOENT && !fs::is_directory(file.parent_path().empty() ? "." : file.parent_path(), ec))
            return "the folder " + file.parent_path().string() + " does not exist";
        return std::string("cannot create the file: ") + std::strerror(err);
    }
    std::string error;
    for (std::size_t done = 0; done < text.size() && error.empty();) {
        const auto written = ::write(fd, text.data() + done, text.size() - done);
        if (written < 0 && errno != EINTR) error = std::string("cannot write: ") + std::strerror(errno);
        if (written > 0) done += static_cast<std::size_t>(written);
    }
    if (error.empty() && ::fsync(fd) != 0) error = std::string("cannot sync: ") + std::strerror(errno);
    if (::close(fd) != 0 && error.empty()) error = std::string("cannot close: ") + std::strerror(errno);
    if (!error.empty()) ::unlink(file.c_str());
    return error;
}

std::string presetText(const Settings& s, const std::string& name, const std::string& schemaRef) {
    try {
        if (schemaRef.empty()) return toOrderedJson(s).dump(2) + "\n";
        nlohmann::ordered_json j{{"$schema", schemaRef}};
        const nlohmann::ordered_json fields = toOrderedJson(s);
        for (const auto& [key, value] : fields.items()) j[key] = value;
        return j.dump(2) + "\n";
    } catch (const nlohmann::json::exception& e) {  // e.g. a string that is not valid UTF-8
        throw SettingsError(name + ": cannot save preset: " + e.what());
    }
}

}  // namespace

nlohmann::json loadJsonFile(const fs::path& file, const std::string& kind) {
    return parseText(readText(file, kind), file.string());
}

Settings loadPreset(const fs::path& file) {
    return fromJson(loadJsonFile(file, "preset"), file.string());
}

void savePresetAtomic(const Settings& s, const fs::path& file, const std::string& schemaRef) {
    const std::string name = file.string();
    if (auto problems = validate(s); !problems.empty()) {
        for (auto& problem : problems) problem = name + ": cannot save invalid settings: " + problem;
        throw SettingsError(problems);
    }
    const std::string text = presetText(s, name, schemaRef);
    const fs::path temp = name + ".tmp-" + std::to_string(::getpid());
    if (auto error = writeSynced(temp, text); !error.empty()) {
        throw SettingsError(name + ": cannot save preset: " + error);
    }
    std::error_code ec;
    fs::rename(temp, file, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(temp, ignored);
        throw SettingsError(name + ": cannot save preset: cannot replace the file: " + ec.message());
    }
}

}  // namespace st
