#include "renderer/compare/report_context.h"

#include "renderer/image/image_output.h"
#include "renderer/scene/crop_window.h"
#include "sampling/core/errors.h"

#include <cstdio>

namespace pdrt {

CompareRender ReportContext::get(const CompareJob& job) const {
  CompareRender r = source(job);
  if (r.image.width != width || r.image.height != height)
    throw InputError(describe(job) + ": its image is " + std::to_string(r.image.width) + "x" +
                     std::to_string(r.image.height) + ", the film " + std::to_string(width) + "x" +
                     std::to_string(height));
  return r;
}

void ReportContext::say(const std::string& line) const {
  if (!o.quiet) std::fprintf(stderr, "pdrt compare: %s\n", line.c_str());
}

void ReportContext::write_png(const std::string& file, const std::vector<float>& rgb) const {
  write_display_png(o.out / file, width, height, rgb);
}

ReportContext report_context(const SceneDesc& base, const CompareOptions& o, const CompareJobSource& source) {
  const PixelRect crop = crop_pixels(base.film.crop_window, base.film.width, base.film.height);
  if (crop.empty()) throw InputError(base.film.size_where + ": film.crop_window covers no pixel of the film");
  return ReportContext{base, o, crop.width(), crop.height(), source};
}

std::vector<float> display_rgb(const Image& im) {
  std::vector<float> out(im.rgb.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = linear_to_srgb(im.rgb[i]);
  return out;
}

}  // namespace pdrt
