#pragma once
// Completion of a typed path (File > Open): the presets, glTF scenes and folders that continue
// what was typed. Pure (the file system only), no ImGui.
#include <filesystem>
#include <string>
#include <vector>

namespace st::ui {

// What `typed` could become: the entries of the folder it names (relative paths from baseDir)
// whose name starts with its last part, folders with a trailing '/', files only if isOpenable; each
// written as `typed`'s folder part + the name, sorted. Hidden entries only if the part starts with '.'.
// A .gltf or .glb (any case): File > Open makes a new preset for it.
bool isGltfFile(const std::filesystem::path& file);
// A preset (.json) or a glTF scene: what File > Open lists and takes.
bool isOpenable(const std::filesystem::path& file);

std::vector<std::string> completePresetPath(const std::filesystem::path& baseDir, const std::string& typed);

// The longest text every candidate starts with ("" for none).
std::string commonPrefix(const std::vector<std::string>& candidates);

}  // namespace st::ui
