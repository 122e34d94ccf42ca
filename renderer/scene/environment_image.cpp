#include "renderer/scene/environment_image.h"

#include "renderer/render/image_module.h"

#include <cmath>
#include <exception>
#include <new>

namespace pdrt {

bool read_environment_image(const std::filesystem::path& path, EnvironmentImage* out, std::string* reason) {
  struct Buffer {
    std::vector<float> px;
    int width = 0, height = 0, channels = 0;
    bool too_big = false;
  } buf;
  PdrtImageRead r{};
  r.context = &buf;
  r.alloc = [](void* ctx, int w, int h, int c) -> float* {
    auto* b = static_cast<Buffer*>(ctx);
    if (w <= 0 || h <= 0 || c <= 0 || (long long)w * h > kMaxEnvironmentTexels) {
      b->too_big = w > 0 && h > 0 && c > 0;
      b->width = w, b->height = h;
      return nullptr;
    }
    try {
      b->px.resize(std::size_t(w) * h * c);
    } catch (const std::bad_alloc&) {
      return nullptr;
    }
    b->width = w, b->height = h, b->channels = c;
    return b->px.data();
  };
  char error[1024] = "";
  try {
    if (image_module().read(path.c_str(), &r, error, sizeof error) != 0) {
      *reason = buf.too_big ? std::to_string(buf.width) + " x " + std::to_string(buf.height) +
                                  " texels is more than the " + std::to_string(kMaxEnvironmentTexels) + " allowed"
                            : std::string(error);
      return false;
    }
  } catch (const std::exception& e) {  // the module itself failed to load
    *reason = e.what();
    return false;
  }
  if (buf.channels <= 0 || buf.px.empty()) {
    *reason = "no pixels";
    return false;
  }
  const int nc = buf.channels;
  const bool srgb = r.integer_format != 0;
  auto decode = [](float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); };
  out->width = buf.width, out->height = buf.height;
  out->rgb.resize(std::size_t(buf.width) * buf.height * 3);
  // Grey + alpha reads as grey; RGB(A...) as RGB.
  const int colour = nc == 2 ? 1 : std::min(nc, 3);
  for (std::size_t i = 0; i < out->rgb.size() / 3; ++i)
    for (int c = 0; c < 3; ++c) {
      const float v = buf.px[i * nc + std::min(c, colour - 1)];
      out->rgb[3 * i + c] = srgb ? decode(v) : v;
    }
  return true;
}

}  // namespace pdrt
