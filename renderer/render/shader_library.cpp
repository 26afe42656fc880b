#include "renderer/render/shader_library.h"

#include <cctype>
#include <cstring>
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

namespace {
// At `pos`, digits then ':' or '(' then digits: the source number and line of a location.
bool readLocation(const std::string& log, std::size_t pos, std::size_t& end, unsigned long& line) {
    auto digits = [&](std::size_t from) {
        std::size_t to = from;
        while (to < log.size() && std::isdigit(static_cast<unsigned char>(log[to]))) ++to;
        return to;
    };
    const std::size_t numberEnd = digits(pos);
    if (numberEnd == pos || numberEnd >= log.size() || (log[numberEnd] != ':' && log[numberEnd] != '(')) return false;
    end = digits(numberEnd + 1);
    if (end == numberEnd + 1) return false;
    line = std::stoul(log.substr(numberEnd + 1, end - numberEnd - 1));
    return true;
}
}  // namespace

std::string nameLogFiles(const std::string& log, const std::vector<std::string>& files) {
    // Mesa writes "0:12(5): error: ...", other drivers "ERROR: 0:12: ..." or "0(12) : error".
    std::string out;
    std::size_t lineStart = 0;
    while (lineStart < log.size()) {
        std::size_t lineEnd = log.find('\n', lineStart);
        lineEnd = lineEnd == std::string::npos ? log.size() : lineEnd + 1;
        std::size_t pos = lineStart;
        for (const char* prefix : {"ERROR: ", "WARNING: "})
            if (log.compare(lineStart, std::strlen(prefix), prefix) == 0) pos += std::strlen(prefix);
        std::size_t end = 0;
        unsigned long line = 0;
        if (readLocation(log, pos, end, line) && line / kLineBase < files.size()) {
            const std::size_t separator = log.find_first_of(":(", pos);
            out += log.substr(lineStart, pos - lineStart) + files[line / kLineBase] + log[separator] +
                   std::to_string(line % kLineBase) + log.substr(end, lineEnd - end);
        } else {
            out += log.substr(lineStart, lineEnd - lineStart);
        }
        lineStart = lineEnd;
    }
    return out;
}

namespace {
// `defines` after the #version line (which must come first), the next line numbered as it was.
void insertDefines(ExpandedShader& shader, const std::string& defines) {
    if (defines.empty()) return;
    const std::size_t versionEnd = shader.text.find('\n');
    if (versionEnd == std::string::npos) throw std::runtime_error("shader " + shader.files.at(0) + " has one line");
    shader.text.insert(versionEnd + 1, defines + lineDirective(0, 2));
}
}  // namespace

gpu::Program linkShaderFiles(const std::string& vertexFile, const std::string& fragmentFile,
                             const std::string& name, const ShaderSources& sources, const std::string& fragmentDefines) {
    const ExpandedShader vs = expandShader(vertexFile, sources);
    ExpandedShader fs = expandShader(fragmentFile, sources);
    insertDefines(fs, fragmentDefines);
    try {
        return gpu::linkProgram(vs.text, fs.text, name);
    } catch (const gpu::ShaderCompileError& e) {
        const auto& files = e.stage == GL_VERTEX_SHADER ? vs.files : fs.files;
        throw std::runtime_error("shader " + (e.stage == GL_VERTEX_SHADER ? vertexFile : fragmentFile) +
                                 " (program " + name + ") failed to compile:\n" + nameLogFiles(e.log, files));
    }
}

SharedProgram sharedProgram(const std::string& key, const std::function<gpu::Program()>& link) {
    thread_local std::map<std::string, std::weak_ptr<const gpu::Program>> live;
    if (SharedProgram p = live[key].lock()) return p;
    SharedProgram p = std::make_shared<const gpu::Program>(link());
    live[key] = p;
    return p;
}

SharedProgram sharedShaderProgram(const std::string& vertexFile, const std::string& fragmentFile, const std::string& name,
                                  const std::string& fragmentDefines) {
    return sharedProgram(vertexFile + "|" + fragmentFile + "|" + name + "|" + fragmentDefines,
                         [&] { return linkShaderFiles(vertexFile, fragmentFile, name, embeddedShaders(), fragmentDefines); });
}

}  // namespace st
