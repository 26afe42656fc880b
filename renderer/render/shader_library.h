#pragma once
// Shader sources embedded at build time (shaders/embed.cmake), with #include "file" resolved and
// #line directives emitted, so a compile error names the file and line it is in.
#include "renderer/gpu/gl.h"

#include <map>
#include <string>
#include <vector>

namespace st {

using ShaderSources = std::map<std::string, std::string>;  // file name -> text

const ShaderSources& embeddedShaders();  // generated from shaders/

struct ExpandedShader {
    std::string text;
    std::vector<std::string> files;  // files[k]: the file of GLSL source-string number k
};

// `file` with its includes inlined; throws std::runtime_error for an unknown file or include and
// for includes nested deeper than 8.
ExpandedShader expandShader(const std::string& file, const ShaderSources& sources = embeddedShaders());

// A driver info log with its "N:LINE(COL)" source-string numbers replaced by file names.
std::string nameLogFiles(const std::string& log, const std::vector<std::string>& files);

// Compiles and links vertexFile + fragmentFile; throws std::runtime_error whose message names the
// file and line of every compile error.
gpu::Program linkShaderFiles(const std::string& vertexFile, const std::string& fragmentFile,
                             const std::string& name, const ShaderSources& sources = embeddedShaders());

}  // namespace st
