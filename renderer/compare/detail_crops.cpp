#include "renderer/compare/detail_crops.h"

#include "renderer/compare/zoomed_crop.h"
#include "renderer/image/image_output.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

std::array<int, 3> detail_window(const Image& ref) {
  // At most the shorter side, so that the crops of an image under 8 pixels read no pixel outside it.
  const int W = ref.width, H = ref.height, c = std::min(std::max(8, std::min(W, H) / 4), std::min(W, H));
  std::vector<double> g(std::size_t(W) * H, 0.0);
  auto L = [&](int x, int y) {
    std::size_t i = 3 * (std::size_t(y) * W + x);
    return double(luminance(Vec3(ref.rgb[i], ref.rgb[i + 1], ref.rgb[i + 2])));
  };
  for (int y = 0; y + 1 < H; ++y)
    for (int x = 0; x + 1 < W; ++x) {
      double a = L(x, y);
      g[std::size_t(y) * W + x] = std::abs(L(x + 1, y) - a) + std::abs(L(x, y + 1) - a);
    }
  std::array<int, 3> best{0, 0, c};
  double best_v = -1;
  const int step = std::max(1, c / 4);
  for (int y0 = 0; y0 + c <= H; y0 += step)
    for (int x0 = 0; x0 + c <= W; x0 += step) {
      double v = 0;
      for (int y = y0; y < y0 + c; ++y)
        for (int x = x0; x < x0 + c; ++x) v += g[std::size_t(y) * W + x];
      if (v > best_v) best_v = v, best = {x0, y0, c};
    }
  return best;
}

void write_detail_crops(const ReportContext& ctx, CompareResults& results) {
  const Image& ref = results.reference.image;
  const std::array<int, 3> win = detail_window(ref);
  const int c = win[2], zoom = std::max(1, 128 / c), gap = 4;
  const int cols = int(ctx.o.samplers.size()) + 1, cw = c * zoom, CW = cols * cw + (cols - 1) * gap;
  results.crops.window = win, results.crops.zoom = zoom;
  for (int n : ctx.o.spp) {
    std::vector<float> rgb(std::size_t(3) * CW * cw, 1.0f);
    auto paste = [&](const Image& im, int col) {
      paste_zoomed(rgb, CW, col * (cw + gap), 0, c, zoom,
                   [&](int x, int y) { return srgb_pixel(im, win[0] + x, win[1] + y); });
    };
    int col = 0;
    for (const auto& name : ctx.o.samplers)
      for (const UniformRun& r : results.runs)
        if (r.sampler == name && r.spp == n) paste(r.image, col++);
    paste(ref, col);
    std::string file = "images/crops-" + std::to_string(n) + ".png";
    write_display_png(ctx.o.out / file, CW, cw, rgb);
    results.crops.files.emplace_back(n, file);
  }
}

}  // namespace pdrt
