#pragma once
// Per-pixel accumulation of filtered samples and the AOVs (sample count, variance of the
// mean, albedo, normal, depth). A pixel is only ever written by the thread rendering it, so
// no locks are needed and results do not depend on scheduling.
#include "renderer/image/image.h"
#include "renderer/render/zeroed_array.h"
#include "renderer/scene/vec3.h"

#include <cstdint>

namespace pdrt {

struct PixelAccum {
  double w = 0, w2 = 0;                             // sum of weights and of squared weights
  double rgb[3] = {0, 0, 0};                        // sum w L
  double lum = 0, lum2 = 0;                         // sum w Y, sum w Y^2 (for the variance of the mean)
  double half_w[2] = {0, 0}, half_lum[2] = {0, 0};  // sum w, sum w Y over even / odd sample indices
  double albedo[3] = {0, 0, 0}, normal[3] = {0, 0, 0}, depth = 0;
  double abs_w = 0;     // sum |w|: AOV weights (filter weights may be negative: Mitchell)
  double depth_w = 0;   // sum |w| over samples that hit something
  int64_t samples = 0;  // samples accumulated into this pixel (splatting: from its neighbours too)
  int64_t traced = 0;   // samples traced from this pixel, dropped ones included
  int64_t dropped = 0;  // samples dropped for a NaN or infinite value (no weight)
  int64_t prefix = 0;   // the pixel's sample budget taken so far (rank selection: of spp, not candidates)
  double norm = 0;      // > 0: value() divides by it instead of sum w (rank selection's unbiased form)
  float lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};  // per-channel sample range (once samples > 0)

  // `half` is the sample index's parity: the two half buffers of the `halves` variance.
  // A sample whose value is NaN or infinite is dropped with no weight, and counted: a black
  // sample at full filter weight would bias the pixel toward 0 without a word.
  void add(const Vec3& L, float weight, const Vec3& alb, const Vec3& n, float z, int half);
  Vec3 value() const;  // normalised weighted mean (Cook §4.2), or sum w L / norm
  double mean_luminance() const;
  double variance_of_mean() const;  // of the luminance
  // The same from the two half buffers (Cycles): (mean_even - mean_odd)^2 / 4; falls back to
  // variance_of_mean() while a half is empty.
  double half_variance_of_mean() const;
  // Mitchell (1987) contrast (max - min) / (max + min) of the samples, per channel.
  double contrast(int channel) const;
};

// Writes pixel p's image values (rgb scaled by `scale`, 2^exposure; the samples plane holds
// its traced count) at pixel index i of `img`, whose planes are sized (sized_image): what
// Film::image does.
void write_image_pixel(const PixelAccum& p, float scale, Image& img, std::size_t i);

class Film {
 public:
  // Every pixel PixelAccum{}, whose bytes are all zero: the pages are zeroed by the kernel as
  // the tiles first touch them (zeroed_array.h).
  Film(int width, int height) : width_(width), height_(height), px_(std::size_t(width) * height) {}
  PixelAccum& at(int x, int y) { return px_[std::size_t(y) * width_ + x]; }
  const PixelAccum& at(int x, int y) const { return px_[std::size_t(y) * width_ + x]; }
  // Maps the pages under pixels [x0, x1) x [y0, y1) writable now (MADV_POPULATE_WRITE), values
  // unchanged. A page first touched by a read maps the shared zero page and faults again, copying
  // it, on the write that follows: on 2 threads that made a 1080p render's kernel time 1.7 s
  // instead of 0.4. Nothing where the kernel cannot (before Linux 5.14).
  void populate(int x0, int x1, int y0, int y1);
  int width() const { return width_; }
  int height() const { return height_; }
  // The samples plane holds the traced counts; rows are converted in parallel (TBB).
  Image image(float exposure_stops) const;
  Image image(float exposure_stops, int x0, int y0, int width, int height) const;  // of a rectangle of the film

  // Bytes the film and its output image need per pixel (for the memory check).
  static constexpr std::size_t kBytesPerPixel = sizeof(PixelAccum) + 12 * sizeof(float);

 private:
  int width_, height_;
  ZeroedArray<PixelAccum> px_;
};

}  // namespace pdrt
