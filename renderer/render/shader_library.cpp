#include "renderer/render/shader_library.h"

#include <map>
#include <sstream>
#include <stdexcept>

namespace st {

const std::map<std::string, std::string>& embeddedShaders();  // generated

namespace {
std::string expand(const std::string& file, int depth) {
    if (depth > 8) throw std::runtime_error("shader include depth exceeded at " + file);
    auto it = embeddedShaders().find(file);
    if (it == embeddedShaders().end()) throw std::runtime_error("no embedded shader " + file);
    std::istringstream in(it->second);
    std::string out, line;
    while (std::getline(in, line)) {
        if (line.rfind("#include \"", 0) == 0) {
            std::string inc = line.substr(10, line.find('"', 10) - 10);
            out += expand(inc, depth + 1);
        } else {
            out += line + "\n";
        }
    }
    return out;
}
}  // namespace

std::string shaderSource(const std::string& file) { return expand(file, 0); }

}  // namespace st
