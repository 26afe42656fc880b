#include "renderer/gpu/gl.h"

#include <stdexcept>

namespace st::gpu {
namespace {
int g_live = 0;

GLuint created(GLuint id) {
    if (id) ++g_live;
    return id;
}
void destroyed() { --g_live; }
}  // namespace

void deleteBuffer(GLuint id) { glDeleteBuffers(1, &id), destroyed(); }
void deleteTexture(GLuint id) { glDeleteTextures(1, &id), destroyed(); }
void deleteFramebuffer(GLuint id) { glDeleteFramebuffers(1, &id), destroyed(); }
void deleteVertexArray(GLuint id) { glDeleteVertexArrays(1, &id), destroyed(); }
void deleteProgram(GLuint id) { glDeleteProgram(id), destroyed(); }
void deleteSampler(GLuint id) { glDeleteSamplers(1, &id), destroyed(); }
void deleteQuery(GLuint id) { glDeleteQueries(1, &id), destroyed(); }

int liveObjectCount() { return g_live; }

Buffer createBuffer(const void* data, GLsizeiptr bytes, GLbitfield flags) {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    // A zero-sized store is invalid; one byte keeps empty scenes legal.
    glNamedBufferStorage(id, bytes > 0 ? bytes : 1, bytes > 0 ? data : nullptr, flags);
    return Buffer(created(id));
}

Texture createTexture(GLenum target) {
    GLuint id = 0;
    glCreateTextures(target, 1, &id);
    return Texture(created(id));
}

Framebuffer createFramebuffer() {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    return Framebuffer(created(id));
}

VertexArray createVertexArray() {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    return VertexArray(created(id));
}

Sampler createSampler() {
    GLuint id = 0;
    glCreateSamplers(1, &id);
    return Sampler(created(id));
}

Query createQuery(GLenum target) {
    GLuint id = 0;
    glCreateQueries(target, 1, &id);
    return Query(created(id));
}

Query genQuery() {
    GLuint id = 0;
    glGenQueries(1, &id);
    return Query(created(id));
}

namespace {
GLuint compileStage(GLenum stage, const std::string& src, const std::string& name) {
    GLuint sh = glCreateShader(stage);
    const char* text = src.c_str();
    glShaderSource(sh, 1, &text, nullptr);
    glCompileShader(sh);
    GLint ok = 0;
    glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096] = {};
        glGetShaderInfoLog(sh, sizeof log, nullptr, log);
        glDeleteShader(sh);
        throw ShaderCompileError(stage, name, log);
    }
    return sh;
}

// Throws with the driver's log if `prog` failed to link; labels it for debug output.
Program linked(Program prog, const std::string& name) {
    GLint ok = 0;
    glGetProgramiv(prog.id(), GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[4096] = {};
        glGetProgramInfoLog(prog.id(), sizeof log, nullptr, log);
        throw std::runtime_error("program " + name + " failed to link:\n" + log);
    }
    glObjectLabel(GL_PROGRAM, prog.id(), -1, name.c_str());
    return prog;
}
}  // namespace

Program linkProgram(const std::string& vertexSrc, const std::string& fragmentSrc,
                    const std::string& name) {
    GLuint vs = compileStage(GL_VERTEX_SHADER, vertexSrc, name + ".vert");
    GLuint fs = 0;
    try {
        fs = compileStage(GL_FRAGMENT_SHADER, fragmentSrc, name + ".frag");
    } catch (...) {
        glDeleteShader(vs);
        throw;
    }
    Program prog(created(glCreateProgram()));
    glAttachShader(prog.id(), vs);
    glAttachShader(prog.id(), fs);
    glLinkProgram(prog.id());
    glDeleteShader(vs);
    glDeleteShader(fs);
    return linked(std::move(prog), name);
}

Program linkComputeProgram(const std::string& computeSrc, const std::string& name) {
    GLuint cs = compileStage(GL_COMPUTE_SHADER, computeSrc, name + ".comp");
    Program prog(created(glCreateProgram()));
    glAttachShader(prog.id(), cs);
    glLinkProgram(prog.id());
    glDeleteShader(cs);
    return linked(std::move(prog), name);
}

DebugGroup::DebugGroup(const char* name) {
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, name);
}
DebugGroup::~DebugGroup() { glPopDebugGroup(); }

}  // namespace st::gpu
