#pragma once
// Headless GL 4.5 core context: EGL on Mesa's surfaceless platform (llvmpipe on a CPU-only
// machine). Only app/ and GL tests create one; the renderer never knows it has no window.
#include <memory>
#include <string>

namespace st {

class HeadlessContext {
public:
    // Throws std::runtime_error with an actionable message when EGL, the surfaceless platform or
    // GL 4.5 core is missing. debug = a KHR_debug context with messages routed to gpu/debug_output.
    static std::unique_ptr<HeadlessContext> create(bool debug);
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    std::string rendererName() const;  // GL_RENDERER + GL_VERSION

private:
    HeadlessContext() = default;
    void* display_ = nullptr;
    void* context_ = nullptr;
};

}  // namespace st
