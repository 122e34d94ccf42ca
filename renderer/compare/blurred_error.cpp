#include "renderer/compare/blurred_error.h"

#include "renderer/compare/image_metrics.h"

#include <cmath>
#include <stdexcept>

namespace pdrt {

namespace {

// One pass of the separable blur over 3-channel rows (step 3) or columns (step 3 W): `n` lines
// of `len` pixels, line i starting at i * line_step.
void blur_lines(const std::vector<float>& in, std::vector<float>& out, const std::vector<double>& g, int len, int n,
                std::size_t pixel_step, std::size_t line_step) {
  const int r = int(g.size()) - 1;
  for (int i = 0; i < n; ++i)
    for (int p = 0; p < len; ++p) {
      double s[3] = {0, 0, 0}, w = 0;
      for (int d = std::max(-r, -p); d <= std::min(r, len - 1 - p); ++d) {
        const double k = g[std::size_t(std::abs(d))];
        const std::size_t j = i * line_step + std::size_t(p + d) * pixel_step;
        for (int c = 0; c < 3; ++c) s[c] += k * in[j + c];
        w += k;
      }
      const std::size_t o = i * line_step + std::size_t(p) * pixel_step;
      for (int c = 0; c < 3; ++c) out[o + c] = float(s[c] / w);  // renormalised inside the image
    }
}

}  // namespace

Image gaussian_blur(const Image& im, double sigma) {
  if (im.rgb.size() != std::size_t(3) * im.width * im.height) throw std::invalid_argument("gaussian_blur: bad image");
  Image out;
  out.width = im.width, out.height = im.height;
  if (!(sigma > 0)) {
    out.rgb = im.rgb;
    return out;
  }
  const int r = int(std::ceil(4 * sigma));
  std::vector<double> g(std::size_t(r) + 1);  // one side of the kernel, g[0] the centre
  for (int d = 0; d <= r; ++d) g[std::size_t(d)] = std::exp(-0.5 * d * d / (sigma * sigma));
  std::vector<float> tmp(im.rgb.size());
  out.rgb.resize(im.rgb.size());
  const std::size_t W = std::size_t(im.width);
  blur_lines(im.rgb, tmp, g, im.width, im.height, 3, 3 * W);   // rows
  blur_lines(tmp, out.rgb, g, im.height, im.width, 3 * W, 3);  // columns
  return out;
}

double blurred_rmse(const Image& test, const Image& reference, double sigma) {
  return rmse(gaussian_blur(test, sigma), gaussian_blur(reference, sigma));
}

std::vector<float> blurred_error_map(const Image& test, const Image& blurred_reference, double sigma) {
  return error_map(gaussian_blur(test, sigma), blurred_reference);
}

}  // namespace pdrt
