#pragma once
// The film's extent on the image plane: pbrt-v4's screen window (§5.2, ProjectiveCamera),
// [x0, x1, y0, y1] along the camera's right and up axes, on the plane at distance 1 for the
// perspective camera and in scene units for the orthographic one. The camera maps film pixel
// (0, 0) to (x0, y1) and (width, height) to (x1, y0).
#include "renderer/scene/scene_desc.h"

#include <array>

namespace pdrt {

// The scene's window when it sets one; else centred: half-height tan(vfov / 2) (perspective)
// or ortho_height / 2 (orthographic), half-width that times width / height.
std::array<float, 4> screen_window(const CameraDesc& camera, int width, int height);

}  // namespace pdrt
