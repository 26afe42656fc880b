#include "ui/path_completion.h"

#include <algorithm>
#include <cctype>

namespace st::ui {

bool isGltfFile(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".gltf" || ext == ".glb";
}

// What File > Open takes: a preset, or a glTF scene of the user's own (a new preset for it).
bool isOpenable(const std::filesystem::path& file) { return file.extension() == ".json" || isGltfFile(file); }
namespace fs = std::filesystem;

std::vector<std::string> completePresetPath(const fs::path& baseDir, const std::string& typed) {
    const auto slash = typed.rfind('/');
    const std::string folderPart = slash == std::string::npos ? "" : typed.substr(0, slash + 1);
    const std::string namePart = typed.substr(folderPart.size());
    fs::path folder = folderPart.empty() ? baseDir : fs::path(folderPart);
    if (!folderPart.empty() && folder.is_relative()) folder = baseDir / folder;
    std::vector<std::string> out;
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (!name.starts_with(namePart) || (name.starts_with('.') && !namePart.starts_with('.'))) continue;
        std::error_code kindError;
        if (it->is_directory(kindError)) out.push_back(folderPart + name + "/");
        else if (isOpenable(it->path())) out.push_back(folderPart + name);
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::string commonPrefix(const std::vector<std::string>& candidates) {
    if (candidates.empty()) return {};
    std::string prefix = candidates.front();
    for (const std::string& c : candidates) {
        const auto [mismatch, _] = std::mismatch(prefix.begin(), prefix.end(), c.begin(), c.end());
        prefix.erase(mismatch, prefix.end());
    }
    return prefix;
}

}  // namespace st::ui
