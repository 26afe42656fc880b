#include "renderer/context/egl_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <stdexcept>

namespace st {
namespace {
[[noreturn]] void fail(const std::string& what) {
    throw std::runtime_error("headless GL: " + what +
                             " (install Mesa's EGL and llvmpipe: scripts/setup.sh installs "
                             "libegl-mesa0 and libgl1-mesa-dri)");
}

EGLDisplay openSurfacelessDisplay() {
    const char* exts = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!exts || !epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless"))
        fail("EGL_MESA_platform_surfaceless is not available");
    EGLDisplay dpy = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY,
                                              nullptr);
    if (dpy == EGL_NO_DISPLAY) fail("eglGetPlatformDisplayEXT(surfaceless) failed");
    EGLint major = 0, minor = 0;
    if (!eglInitialize(dpy, &major, &minor)) fail("eglInitialize failed");
    return dpy;
}

EGLContext createCoreContext(EGLDisplay dpy, bool debug) {
    if (!eglBindAPI(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API) failed");
    const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                              EGL_CONTEXT_OPENGL_PROFILE_MASK,
                              EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_CONTEXT_OPENGL_DEBUG,
                              debug ? EGL_TRUE : EGL_FALSE, EGL_NONE};
    EGLContext ctx = eglCreateContext(dpy, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
    if (ctx == EGL_NO_CONTEXT) fail("no OpenGL 4.5 core context (eglCreateContext failed)");
    if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
        eglDestroyContext(dpy, ctx);
        fail("eglMakeCurrent without a surface failed");
    }
    return ctx;
}
}  // namespace

std::unique_ptr<HeadlessContext> HeadlessContext::create(bool debug) {
    std::unique_ptr<HeadlessContext> c(new HeadlessContext());
    EGLDisplay dpy = openSurfacelessDisplay();
    c->display_ = dpy;
    c->context_ = createCoreContext(dpy, debug);
    if (epoxy_gl_version() < 45) fail("OpenGL 4.5 is required, the driver gives " +
                                      std::to_string(epoxy_gl_version() / 10) + "." +
                                      std::to_string(epoxy_gl_version() % 10));
    return c;
}

HeadlessContext::~HeadlessContext() {
    auto dpy = static_cast<EGLDisplay>(display_);
    if (!dpy) return;
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_) eglDestroyContext(dpy, static_cast<EGLContext>(context_));
    eglTerminate(dpy);
}

std::string HeadlessContext::rendererName() const {
    auto str = [](GLenum e) {
        auto s = reinterpret_cast<const char*>(glGetString(e));
        return std::string(s ? s : "?");
    };
    return str(GL_RENDERER) + ", " + str(GL_VERSION);
}

}  // namespace st
