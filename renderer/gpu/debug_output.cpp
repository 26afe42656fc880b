#include "renderer/gpu/debug_output.h"

#include "renderer/gpu/gl.h"

#include <cstdio>
#include <mutex>

namespace st::gpu {
namespace {
std::mutex g_mutex;
std::vector<std::string> g_serious;

const char* severityName(GLenum s) {
    switch (s) {
    case GL_DEBUG_SEVERITY_HIGH: return "high";
    case GL_DEBUG_SEVERITY_MEDIUM: return "medium";
    case GL_DEBUG_SEVERITY_LOW: return "low";
    default: return "note";
    }
}

void GLAPIENTRY onMessage(GLenum, GLenum type, GLuint id, GLenum severity, GLsizei,
                          const GLchar* message, const void*) {
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;  // group pushes, driver chatter
    std::string text = std::string("GL [") + severityName(severity) + "] id " +
                       std::to_string(id) + ": " + message;
    std::fprintf(stderr, "%s\n", text.c_str());
    bool serious = severity == GL_DEBUG_SEVERITY_HIGH || severity == GL_DEBUG_SEVERITY_MEDIUM ||
                   type == GL_DEBUG_TYPE_ERROR;
    if (serious) {
        std::lock_guard lock(g_mutex);
        g_serious.push_back(std::move(text));
    }
}
}  // namespace

void enableDebugOutput() {
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onMessage, nullptr);
}

int seriousDebugMessageCount() {
    std::lock_guard lock(g_mutex);
    return static_cast<int>(g_serious.size());
}

std::vector<std::string> seriousDebugMessages() {
    std::lock_guard lock(g_mutex);
    return g_serious;
}

}  // namespace st::gpu
