#pragma once
// One shadow method seen on another preset's view: the method's cascades, filter, bias and every
// other setting, with the view's scene, ground, camera, light and camera path. `compare` renders B
// this way on A's view; the editor's A/B split renders A this way on the live view.
#include "renderer/settings/settings.h"

namespace st {

inline Settings methodOnView(Settings method, const Settings& view) {
    method.scene = view.scene;
    method.ground = view.ground;
    method.camera = view.camera;
    method.light = view.light;
    method.path = view.path;
    return method;
}

}  // namespace st
