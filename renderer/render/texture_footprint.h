#pragma once
// How much of the texture one pixel covers at a surface point: the uv derivatives the MIP
// filters need. pbrt-v4 (Camera::Approximate_dp_dxy, §10.1.1) approximates the camera's ray
// differentials at any point, camera hit or not: the rays through the neighbouring pixels'
// centres (pinhole at the camera position), intersected with the tangent plane at the point,
// give dp/dx and dp/dy, scaled by max(1/8, 1/sqrt(spp)) since spp samples per pixel each see
// a proportionally smaller footprint. The same estimate serves after bounces (as in pbrt-v4:
// a blurrier lookup than a true differential after a curved reflector, never a sharper one).
// dp/dx = (du/dx) dp/du + (dv/dx) dp/dv is then solved for du/dx, dv/dx in least squares.
#include "renderer/render/embree_scene.h"
#include "renderer/scene/scene_desc.h"

namespace pdrt {

struct TextureCoords {
  float u = 0, v = 0;
  float dudx = 0, dvdx = 0, dudy = 0, dvdy = 0;
};

class TextureFootprint {
 public:
  TextureFootprint(const CameraDesc& camera, int film_width, int film_height, int spp);
  TextureCoords at(const SurfaceHit& hit) const;

 private:
  Vec3 eye_, forward_, right_, up_;
  float pixel_ = 0;     // image-plane height of a pixel at unit distance along forward_, times the spp scale
  float pixel_x_ = 0;   // its width (screen windows may stretch pixels)
  bool ortho_ = false;  // pixel_ and pixel_x_ are in scene units, rays parallel
};

}  // namespace pdrt
