#pragma once
// Shader sources embedded at build time (shaders/embed.cmake), with #include "file" resolved and
// #line directives emitted, so a compile error names the file and line it is in.
#include "renderer/gpu/gl.h"

#include <functional>
#include <map>
#include <memory>
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
// file and line of every compile error. fragmentDefines ("#define NAME VALUE" lines) go right
// after the fragment shader's #version line.
gpu::Program linkShaderFiles(const std::string& vertexFile, const std::string& fragmentFile,
                             const std::string& name, const ShaderSources& sources = embeddedShaders(),
                             const std::string& fragmentDefines = {});

// A program linked once and shared by every renderer and pass of the current context that asks
// for the same files while one of them holds it. Why: llvmpipe JIT-compiles shader variants per
// program object and keeps a bounded number of instructions per context; several renderers each
// linking main.frag (a tune keeps one per view) pushed the variants past that bound, so they were
// evicted and recompiled frame after frame (docs/tuning.md#speed). Programs are per thread, as a
// context is current on one thread; a thread must not switch contexts while it holds programs.
using SharedProgram = std::shared_ptr<const gpu::Program>;
SharedProgram sharedShaderProgram(const std::string& vertexFile, const std::string& fragmentFile, const std::string& name,
                                  const std::string& fragmentDefines = {});
// The same for a program `link` makes (a compute program), keyed by `key`.
SharedProgram sharedProgram(const std::string& key, const std::function<gpu::Program()>& link);

}  // namespace st
