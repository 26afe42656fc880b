#include "renderer/render/gpu_timer.h"

namespace st {

void GpuTimers::beginFrame(int count) {
    // Exactly as many as needed, so a lower cascade count gives its queries back.
    while (static_cast<int>(queries_.size()) < 2 * count) queries_.push_back(gpu::createQuery(GL_TIMESTAMP));
    while (static_cast<int>(queries_.size()) > 2 * count) queries_.pop_back();
}

void GpuTimers::begin(int index) { glQueryCounter(queries_[2 * index].id(), GL_TIMESTAMP); }

void GpuTimers::end(int index) { glQueryCounter(queries_[2 * index + 1].id(), GL_TIMESTAMP); }

double GpuTimers::milliseconds(int index) const {
    GLuint64 t0 = 0, t1 = 0;
    glGetQueryObjectui64v(queries_[2 * index].id(), GL_QUERY_RESULT, &t0);
    glGetQueryObjectui64v(queries_[2 * index + 1].id(), GL_QUERY_RESULT, &t1);
    return t1 > t0 ? static_cast<double>(t1 - t0) * 1e-6 : 0.0;
}

}  // namespace st
