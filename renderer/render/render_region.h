#pragma once
// The rectangle of the image a render computes. pbrt-v4 §5.4.2 crop window: only `crop` is
// output, but the pixels that can change it are rendered too (docs/renderer.md, "Crop
// window"): a splatted sample reaches the filter's radius plus one pixel, and each adaptive
// round lets a pixel's neighbours decide it refines.
#include "renderer/scene/crop_window.h"
#include "renderer/scene/scene_desc.h"

namespace pdrt {

struct RenderRegion {
  PixelRect crop;                  // the output, in image pixels
  PixelRect rect;                  // the rendered rectangle, in image pixels: crop plus margin, within the image
  int margin_rounds = 0;           // adaptive rounds (round 0 included) the margin covers
  bool metric_needs_mean = false;  // the adaptive metric compares with the image's mean (the crop's)

  // The crop in film coordinates (the rendered rectangle's pixel (0, 0) at image pixel rect.x0, rect.y0).
  int crop_x0() const { return crop.x0 - rect.x0; }
  int crop_y0() const { return crop.y0 - rect.y0; }
  bool in_crop(int image_x, int image_y) const {
    return image_x >= crop.x0 && image_x < crop.x1 && image_y >= crop.y0 && image_y < crop.y1;
  }
};

// The region of `desc`'s film, whose crop window covers a pixel (check_render_settings).
RenderRegion render_region(const SceneDesc& desc);

// Warns (unless `quiet`) that a cropped adaptive render may differ from the crop of the full
// render: when the metric compares with the crop's mean, or refinement ran `rounds` past the
// rounds the margin covers.
void warn_adaptive_crop(const SceneDesc& desc, const RenderRegion& region, int rounds, bool quiet);

}  // namespace pdrt
