#include "renderer/render/shader_library.h"

#include <regex>
#include <sstream>
#include <stdexcept>

namespace st {
namespace {
constexpr int kMaxIncludeDepth = 8;
// File k's lines are numbered from k * kLineBase: Mesa gives some errors the source-string number
// 0 whatever #line said (an undeclared identifier, seen with Mesa 22.3), but keeps line numbers.
constexpr int kLineBase = 100000;

std::string lineDirective(int index, int line) {
    return "#line " + std::to_string(index * kLineBase + line) + " " + std::to_string(index) + "\n";
}

int fileIndex(ExpandedShader& out, const std::string& file) {
    for (std::size_t k = 0; k < out.files.size(); ++k)
        if (out.files[k] == file) return static_cast<int>(k);
    out.files.push_back(file);
    return static_cast<int>(out.files.size()) - 1;
}

// GLSL's #line takes a source-string number, not a name (GL 4.5 has no named strings without
// ARB_shading_language_include): each file gets a number and a line range, and nameLogFiles()
// maps them back.
void expandInto(ExpandedShader& out, const std::string& file, const ShaderSources& sources, int depth) {
    if (depth > kMaxIncludeDepth) throw std::runtime_error("shader include depth exceeded at " + file);
    const auto it = sources.find(file);
    if (it == sources.end()) throw std::runtime_error("no embedded shader " + file);
    const int index = fileIndex(out, file);
    if (depth > 0) out.text += lineDirective(index, 1);
    std::istringstream in(it->second);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (line.rfind("#include \"", 0) != 0) {
            out.text += line + "\n";
            continue;
        }
        expandInto(out, line.substr(10, line.find('"', 10) - 10), sources, depth + 1);
        out.text += lineDirective(index, number + 1);
    }
}
}  // namespace

ExpandedShader expandShader(const std::string& file, const ShaderSources& sources) {
    ExpandedShader out;
    expandInto(out, file, sources, 0);
    return out;
}

std::string nameLogFiles(const std::string& log, const std::vector<std::string>& files) {
    // Mesa writes "0:12(5): error: ...", other drivers "ERROR: 0:12: ..." or "0(12) : error".
    static const std::regex location(R"((^|\n)((?:ERROR|WARNING): )?(\d+)([:(])(\d+))");
    std::string out;
    std::size_t last = 0;
    for (auto i = std::sregex_iterator(log.begin(), log.end(), location); i != std::sregex_iterator(); ++i) {
        const std::smatch& m = *i;
        const unsigned long line = std::stoul(m[5].str());
        const std::size_t file = line / kLineBase;
        if (file >= files.size()) continue;
        out += log.substr(last, static_cast<std::size_t>(m.position(0)) - last);
        out += m[1].str() + m[2].str() + files[file] + m[4].str() + std::to_string(line % kLineBase);
        last = static_cast<std::size_t>(m.position(0) + m.length(0));
    }
    return out + log.substr(last);
}

gpu::Program linkShaderFiles(const std::string& vertexFile, const std::string& fragmentFile,
                             const std::string& name, const ShaderSources& sources) {
    const ExpandedShader vs = expandShader(vertexFile, sources);
    const ExpandedShader fs = expandShader(fragmentFile, sources);
    try {
        return gpu::linkProgram(vs.text, fs.text, name);
    } catch (const gpu::ShaderCompileError& e) {
        const auto& files = e.stage == GL_VERTEX_SHADER ? vs.files : fs.files;
        throw std::runtime_error("shader " + (e.stage == GL_VERTEX_SHADER ? vertexFile : fragmentFile) +
                                 " (program " + name + ") failed to compile:\n" + nameLogFiles(e.log, files));
    }
}

}  // namespace st
