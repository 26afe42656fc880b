#pragma once
// A uniform buffer holding one block struct of shaders/interface.h (st::gpu_if::*Block).
#include "renderer/gpu/gl.h"

namespace st::gpu {

template <class Block>
class UniformBuffer {
public:
    // Needs a current context; the contents start zeroed.
    UniformBuffer() {
        const Block zero{};
        buffer_ = createBuffer(&zero, sizeof(Block), GL_DYNAMIC_STORAGE_BIT);
    }
    // Copies `block` into the buffer. Between draws this is safe: GL keeps the contents that
    // earlier draws saw.
    void upload(const Block& block) { glNamedBufferSubData(buffer_.id(), 0, sizeof(Block), &block); }
    void bind(GLuint binding) const { glBindBufferBase(GL_UNIFORM_BUFFER, binding, buffer_.id()); }

private:
    Buffer buffer_;
};

}  // namespace st::gpu
