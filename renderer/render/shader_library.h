#pragma once
// Shader sources embedded at build time (shaders/embed.cmake), with #include "file" resolved.
#include <string>

namespace st {

// Throws std::runtime_error for an unknown file or include.
std::string shaderSource(const std::string& file);

}  // namespace st
