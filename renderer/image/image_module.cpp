#include "renderer/image/image_module.h"

#include "sampling/core/errors.h"
#include "sampling/core/install_paths.h"

#include <dlfcn.h>

#include <cmath>
#include <cstdlib>
#include <exception>
#include <new>
#include <filesystem>
#include <string>

namespace pdrt {
namespace fs = std::filesystem;

namespace {

fs::path module_path() {
  if (const char* env = std::getenv("PDRT_IMAGE_MODULE"); env && *env) return env;
  std::error_code ec;
  const fs::path exe = executable_path();
  if (!exe.empty()) {
    fs::path beside = exe.parent_path() / PDRT_IMAGE_MODULE_FILE_NAME;
    if (fs::exists(beside, ec)) return beside;
  }
  if (auto installed = installed_path(fs::path("lib/pdrt") / PDRT_IMAGE_MODULE_FILE_NAME)) return *installed;
  return PDRT_IMAGE_MODULE_BUILD_PATH;
}

const PdrtImageModule& load() {
  const fs::path path = module_path();
  // Never closed: OpenImageIO keeps threads and static state until the process exits.
  void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) throw InputError("cannot load the image module " + path.string() + ": " + ::dlerror());
  auto entry = reinterpret_cast<const PdrtImageModule* (*)()>(::dlsym(handle, PDRT_IMAGE_MODULE_SYMBOL));
  if (!entry) throw InputError("image module " + path.string() + ": " + ::dlerror());
  const PdrtImageModule* m = entry();
  if (!m || m->abi != PDRT_IMAGE_MODULE_ABI)
    throw InputError("image module " + path.string() + ": ABI version " + std::to_string(m ? m->abi : -1) +
                     ", expected " + std::to_string(PDRT_IMAGE_MODULE_ABI) + " (rebuild pdrt)");
  return *m;
}

}  // namespace

const PdrtImageModule& image_module() {
  // A throwing initialiser leaves the static uninitialised: the next call tries again.
  static const PdrtImageModule& m = load();
  return m;
}

bool read_linear_rgb(const fs::path& path, long long max_texels, LinearRgbImage* out, std::string* reason) {
  struct Buffer {
    std::vector<float> px;
    int width = 0, height = 0, channels = 0;
    long long max_texels = 0;
    bool too_big = false;
  } buf;
  buf.max_texels = max_texels;
  PdrtImageRead r{};
  r.context = &buf;
  r.alloc = [](void* ctx, int w, int h, int c) -> float* {
    auto* b = static_cast<Buffer*>(ctx);
    if (w <= 0 || h <= 0 || c <= 0 || (b->max_texels > 0 && (long long)w * h > b->max_texels)) {
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
                                  " texels is more than the " + std::to_string(max_texels) + " allowed"
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
  const int colour = nc == 2 ? 1 : std::min(nc, 3);  // grey + alpha reads as grey
  for (std::size_t i = 0; i < out->rgb.size() / 3; ++i)
    for (int c = 0; c < 3; ++c) {
      const float v = buf.px[i * nc + std::min(c, colour - 1)];
      out->rgb[3 * i + c] = srgb ? decode(v) : v;
    }
  return true;
}

}  // namespace pdrt
