#include "renderer/render/image_output.h"

#include "sampling/core/atomic_file.h"
#include "sampling/core/errors.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>

namespace pdrt {

namespace OIIO = OIIO_NAMESPACE;

namespace {

std::string lower_ext(const std::filesystem::path& p) {
  std::string e = p.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return e;
}

bool is_float_format(const std::string& ext) { return ext == ".exr" || ext == ".tif" || ext == ".tiff"; }

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
  OIIO::ImageSpec spec(img.width, img.height, nc, linear ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  spec.channelnames = names;
  if (exr) spec.z_channel = nc - 1;
  spec.attribute("oiio:ColorSpace", linear ? "linear" : "sRGB");
  if (exr) spec.attribute("compression", "zip");
  for (const auto& [k, v] : metadata) spec.attribute(k, v);

  std::vector<float> pixels(n * nc);
  for (std::size_t i = 0; i < n; ++i) {
    float* o = &pixels[i * nc];
    for (int c = 0; c < 3; ++c) o[c] = linear ? img.rgb[3 * i + c] : linear_to_srgb(img.rgb[3 * i + c]);
    if (exr) {
      o[3] = img.samples[i], o[4] = img.variance[i];
      for (int c = 0; c < 3; ++c) o[5 + c] = img.albedo[3 * i + c], o[8 + c] = img.normal[3 * i + c];
      o[11] = img.depth[i];
    }
  }
  write_path_atomically(path, [&](const std::filesystem::path& tmp) {
    auto out = OIIO::ImageOutput::create(ext.substr(1));
    if (!out) throw InputError(path.string() + ": cannot create an image writer: " + OIIO::geterror());
    if (!out->open(tmp.string(), spec)) throw InputError(path.string() + ": " + out->geterror());
    // OIIO converts float to the file's type (8-bit quantisation with rounding).
    if (!out->write_image(OIIO::TypeDesc::FLOAT, pixels.data())) throw InputError(path.string() + ": " + out->geterror());
    if (!out->close()) throw InputError(path.string() + ": " + out->geterror());
  });
}

void write_display_png(const std::filesystem::path& path, int width, int height, const std::vector<float>& rgb) {
  OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:ColorSpace", "sRGB");
  write_path_atomically(path, [&](const std::filesystem::path& tmp) {
    auto out = OIIO::ImageOutput::create("png");
    if (!out || !out->open(tmp.string(), spec)) throw InputError(path.string() + ": cannot write PNG");
    if (!out->write_image(OIIO::TypeDesc::FLOAT, rgb.data()) || !out->close())
      throw InputError(path.string() + ": " + out->geterror());
  });
}

Image read_image_rgb(const std::filesystem::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw InputError(path.string() + ": cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  Image img;
  img.width = spec.width, img.height = spec.height;
  std::vector<float> px(std::size_t(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()))
    throw InputError(path.string() + ": " + in->geterror());
  const bool srgb = spec.format == OIIO::TypeDesc::UINT8 || spec.format == OIIO::TypeDesc::UINT16;
  auto decode = [&](float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); };
  img.rgb.resize(std::size_t(spec.width) * spec.height * 3);
  for (std::size_t i = 0; i < img.rgb.size() / 3; ++i)
    for (int c = 0; c < 3; ++c) {
      float v = px[i * spec.nchannels + std::min(c, spec.nchannels - 1)];
      img.rgb[3 * i + c] = srgb ? decode(v) : v;
    }
  return img;
}

}  // namespace pdrt
