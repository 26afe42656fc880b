#pragma once
// The only header that pulls in the GL loader. Move-only RAII handles over GL 4.5 DSA objects,
// in the spirit of Fwog: one owner per object, nothing leaks when settings reallocate.
#include <epoxy/gl.h>

#include <stdexcept>
#include <string>
#include <utility>

namespace st::gpu {

// Owns one GL name; Deleter is a function that deletes one name.
template <void (*Deleter)(GLuint)>
class Handle {
public:
    Handle() = default;
    explicit Handle(GLuint id) : id_(id) {}
    Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
    Handle& operator=(Handle&& o) noexcept {
        if (this != &o) {
            reset();
            id_ = std::exchange(o.id_, 0);
        }
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    ~Handle() { reset(); }
    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() {
        if (id_) Deleter(id_);
        id_ = 0;
    }

private:
    GLuint id_ = 0;
};

void deleteBuffer(GLuint id);
void deleteTexture(GLuint id);
void deleteFramebuffer(GLuint id);
void deleteVertexArray(GLuint id);
void deleteProgram(GLuint id);
void deleteSampler(GLuint id);
void deleteQuery(GLuint id);

using Buffer = Handle<deleteBuffer>;
using Texture = Handle<deleteTexture>;
using Framebuffer = Handle<deleteFramebuffer>;
using VertexArray = Handle<deleteVertexArray>;
using Program = Handle<deleteProgram>;
using Sampler = Handle<deleteSampler>;
using Query = Handle<deleteQuery>;

Buffer createBuffer(const void* data, GLsizeiptr bytes, GLbitfield flags = 0);
Texture createTexture(GLenum target);
Framebuffer createFramebuffer();
VertexArray createVertexArray();
Sampler createSampler();
Query createQuery(GLenum target);
// A query name with no target yet (glGenQueries): its first glBeginQuery gives it one. For the
// pipeline-statistics targets, which Mesa 22's glCreateQueries rejects as GL_INVALID_ENUM.
Query genQuery();

// Number of GL objects alive that these wrappers created (tests check reallocation leaks none).
int liveObjectCount();

// A stage failed to compile: the driver's info log as it is (source-string numbers, no names).
struct ShaderCompileError : std::runtime_error {
    ShaderCompileError(GLenum stageIn, const std::string& name, const std::string& logIn)
        : std::runtime_error("shader " + name + " failed to compile:\n" + logIn), stage(stageIn), log(logIn) {}
    GLenum stage;
    std::string log;
};

// Throws ShaderCompileError if a stage fails to compile, std::runtime_error if linking fails.
Program linkProgram(const std::string& vertexSrc, const std::string& fragmentSrc,
                    const std::string& name);

// A compute program from one stage; throws like linkProgram.
Program linkComputeProgram(const std::string& computeSrc, const std::string& name);

// Scoped KHR_debug group, shown in frame debuggers and in debug messages.
class DebugGroup {
public:
    explicit DebugGroup(const char* name);
    ~DebugGroup();
    DebugGroup(const DebugGroup&) = delete;
    DebugGroup& operator=(const DebugGroup&) = delete;
};

}  // namespace st::gpu
