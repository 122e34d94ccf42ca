#include "renderer/image/image_output.h"

#include "sampling/core/atomic_file.h"
#include "sampling/core/errors.h"

#include "renderer/image/image_module.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <new>

namespace pdrt {

namespace {

std::string lower_ext(const std::filesystem::path& p) {
  std::string e = p.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return e;
}

bool is_float_format(const std::string& ext) { return ext == ".exr" || ext == ".tif" || ext == ".tiff"; }

// Writes through the image module into the temporary file, renamed over `path` when complete.
void write_through_module(const std::filesystem::path& path, PdrtImageWrite w, const Metadata& attributes) {
  const PdrtImageModule& m = image_module();
  std::vector<PdrtImageAttribute> attrs;
  for (const auto& [k, v] : attributes) attrs.push_back({k.c_str(), v.c_str()});
  w.attributes = attrs.data();
  w.attribute_count = int(attrs.size());
  write_path_atomically(path, [&](const std::filesystem::path& tmp) {
    const std::string tmp_name = tmp.string();
    w.path = tmp_name.c_str();
    char error[1024];
    if (m.write(&w, error, sizeof error) != 0) throw InputError(path.string() + ": " + error);
  });
}

}  // namespace

float linear_to_srgb(float v) {
  if (!(v > 0)) return 0;
  if (v >= 1) return 1;
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1 / 2.4f) - 0.055f;
}

void check_image_extension(const std::filesystem::path& path) {
  std::string e = lower_ext(path);
  if (e != ".exr" && e != ".png" && e != ".jpg" && e != ".jpeg" && e != ".tif" && e != ".tiff")
    throw UsageError(path.string() + ": output must end in .exr, .png, .jpg, .jpeg, .tif or .tiff");
}

void require_image_io() { image_module(); }

void write_image(const std::filesystem::path& path, const Image& img, const Metadata& metadata) {
  check_image_extension(path);
  const std::string ext = lower_ext(path);
  const bool exr = ext == ".exr", linear = is_float_format(ext);
  const std::size_t n = std::size_t(img.width) * img.height;
  std::vector<std::string> names = {"R", "G", "B"};
  if (exr) {
    for (const char* c : {"samples", "variance", "albedo.R", "albedo.G", "albedo.B", "N.X", "N.Y", "N.Z", "Z"})
      names.push_back(c);
  }
  const int nc = int(names.size());
  Metadata attributes = {{"oiio:ColorSpace", linear ? "linear" : "sRGB"}};
  if (exr) attributes.push_back({"compression", "zip"});
  attributes.insert(attributes.end(), metadata.begin(), metadata.end());

  // Interleaved in parallel into memory nothing zeroed first: a 1080p EXR's 100 MB, zeroed and
  // filled on one thread, took a quarter of a second before the file was opened (2026-12-06).
  const std::unique_ptr<float[]> pixels(new float[n * std::size_t(nc)]);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      float* o = &pixels[i * nc];
      for (int c = 0; c < 3; ++c) o[c] = linear ? img.rgb[3 * i + c] : linear_to_srgb(img.rgb[3 * i + c]);
      if (exr) {
        o[3] = img.samples[i], o[4] = img.variance[i];
        for (int c = 0; c < 3; ++c) o[5 + c] = img.albedo[3 * i + c], o[8 + c] = img.normal[3 * i + c];
        o[11] = img.depth[i];
      }
    }
  });
  std::vector<const char*> channel_names;
  for (const auto& c : names) channel_names.push_back(c.c_str());
  const std::string format = ext.substr(1);
  PdrtImageWrite w{};
  w.format = format.c_str();
  w.width = img.width, w.height = img.height, w.channels = nc;
  w.channel_names = channel_names.data();
  w.z_channel = exr ? nc - 1 : -1;
  w.uint8 = !linear;
  w.pixels = pixels.get();
  write_through_module(path, w, attributes);
}

void write_display_png(const std::filesystem::path& path, int width, int height, const std::vector<float>& rgb) {
  PdrtImageWrite w{};
  w.format = "png";
  w.width = width, w.height = height, w.channels = 3;
  w.z_channel = -1;
  w.uint8 = 1;
  w.pixels = rgb.data();
  write_through_module(path, w, {{"oiio:ColorSpace", "sRGB"}});
}

void write_linear_rgb(const std::filesystem::path& path, int width, int height, const std::vector<float>& rgb,
                      const Metadata& metadata) {
  const std::string ext = lower_ext(path);
  if (!is_float_format(ext)) throw UsageError(path.string() + ": linear RGB goes to .exr, .tif or .tiff");
  PdrtImageWrite w{};
  const std::string format = ext == ".exr" ? "exr" : "tiff";
  w.format = format.c_str();
  w.width = width, w.height = height, w.channels = 3;
  w.z_channel = -1;
  w.pixels = rgb.data();
  Metadata attributes = {{"oiio:ColorSpace", "linear"}};
  if (ext == ".exr") attributes.push_back({"compression", "zip"});
  attributes.insert(attributes.end(), metadata.begin(), metadata.end());
  write_through_module(path, w, attributes);
}

Image read_image_rgb(const std::filesystem::path& path) {
  LinearRgbImage in;
  std::string reason;
  if (!read_linear_rgb(path, 0, &in, &reason)) throw InputError(path.string() + ": " + reason);
  Image img;
  img.width = in.width, img.height = in.height, img.rgb = std::move(in.rgb);
  return img;
}

}  // namespace pdrt
