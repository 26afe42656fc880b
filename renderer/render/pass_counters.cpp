#include "renderer/render/pass_counters.h"

namespace st {
namespace {
constexpr std::array<GLenum, PassCounters::kTargets> kTargetsOf = {
    GL_VERTICES_SUBMITTED_ARB, GL_PRIMITIVES_SUBMITTED_ARB, GL_CLIPPING_OUTPUT_PRIMITIVES_ARB,
    GL_FRAGMENT_SHADER_INVOCATIONS_ARB, GL_COMPUTE_SHADER_INVOCATIONS_ARB, GL_SAMPLES_PASSED};
}  // namespace

PassCounters::PassCounters()
    : supported_(epoxy_gl_version() >= 46 || epoxy_has_gl_extension("GL_ARB_pipeline_statistics_query")) {}

void PassCounters::beginFrame(int count) {
    if (!supported_) return;
    while (static_cast<int>(queries_.size()) < count) {
        std::array<gpu::Query, kTargets> slot;
        for (gpu::Query& q : slot) q = gpu::genQuery();  // see genQuery: not createQuery
        queries_.push_back(std::move(slot));
    }
    while (static_cast<int>(queries_.size()) > count) queries_.pop_back();
    ran_.assign(queries_.size(), false);
}

void PassCounters::begin(int slot) {
    if (!supported_) return;
    for (int t = 0; t < kTargets; ++t)
        glBeginQuery(kTargetsOf[std::size_t(t)], queries_[std::size_t(slot)][std::size_t(t)].id());
}

void PassCounters::end(int slot) {
    if (!supported_) return;
    for (int t = 0; t < kTargets; ++t) glEndQuery(kTargetsOf[std::size_t(t)]);
    ran_[std::size_t(slot)] = true;
}

PassWork PassCounters::read(int slot) const {
    PassWork w;
    if (!supported_ || !ran_[std::size_t(slot)]) return w;
    std::array<GLuint64, kTargets> v{};
    for (int t = 0; t < kTargets; ++t)
        glGetQueryObjectui64v(queries_[std::size_t(slot)][std::size_t(t)].id(), GL_QUERY_RESULT, &v[std::size_t(t)]);
    w.vertices = v[0];
    w.primitives = v[1];
    w.clippedPrimitives = v[2];
    w.fragments = v[3];
    w.computeInvocations = v[4];
    w.samplesPassed = v[5];
    return w;
}

}  // namespace st
