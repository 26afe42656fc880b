#pragma once
// Helpers shared by the GL tests: render a Settings value, project world points to pixels.
#include "renderer/image/image_io.h"
#include "renderer/render/renderer.h"

#include <glm/glm.hpp>

#include <optional>

namespace st::test {

// The built-in box-over-plane scene (a 2 m box 2 m above a 40 m ground) seen from `eye` toward
// `target`, the camera's far plane at `farPlane`; everything else default.
inline Settings boxOverPlaneView(glm::vec3 eye, glm::vec3 target, float farPlane) {
    Settings s;
    s.scene = "builtin:box-over-plane";
    s.camera.position = eye;
    s.camera.target = target;
    s.camera.farPlane = farPlane;
    return s;
}

inline Rgba8Image renderImage(Renderer& r, const Settings& s) {
    r.render(s);
    return {r.width(), r.height(), r.readRgba8()};
}

// Pixel (column, row from the top) where a world point lands, or nullopt if off screen.
inline std::optional<glm::ivec2> projectToPixel(const Renderer& r, glm::vec3 ws) {
    glm::vec4 cs = r.plan().csProj * r.plan().vsView * glm::vec4(ws, 1.0f);
    if (cs.w <= 0.0f) return std::nullopt;
    glm::vec3 ndc = glm::vec3(cs) / cs.w;
    int x = int((ndc.x * 0.5f + 0.5f) * float(r.width()));
    int y = int((0.5f - ndc.y * 0.5f) * float(r.height()));
    if (x < 0 || y < 0 || x >= r.width() || y >= r.height()) return std::nullopt;
    return glm::ivec2(x, y);
}

inline glm::u8vec4 pixelAt(const Rgba8Image& img, glm::ivec2 p) {
    const std::uint8_t* q = &img.pixels[(std::size_t(p.y) * img.width + p.x) * 4];
    return {q[0], q[1], q[2], q[3]};
}

}  // namespace st::test
