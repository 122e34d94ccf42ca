// The image module: reads and writes image files through OpenImageIO behind the C table of
// image_module_abi.h. Built as a CMake MODULE library; the only code in pdrt that links OIIO.
#include "renderer/image/image_module_abi.h"

#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace {

namespace OIIO = OIIO_NAMESPACE;

int fail(char* error, size_t size, const std::string& message) {
  if (size > 0) std::snprintf(error, size, "%s", message.c_str());
  return 1;
}

int write_image(const PdrtImageWrite* w, char* error, size_t error_size) {
  try {
    OIIO::ImageSpec spec(w->width, w->height, w->channels, w->uint8 ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
    if (w->channel_names) spec.channelnames.assign(w->channel_names, w->channel_names + w->channels);
    if (w->z_channel >= 0) spec.z_channel = w->z_channel;
    for (int i = 0; i < w->attribute_count; ++i) spec.attribute(w->attributes[i].key, w->attributes[i].value);
    auto out = OIIO::ImageOutput::create(w->format);
    if (!out) return fail(error, error_size, "cannot create an image writer: " + OIIO::geterror());
    if (!out->open(w->path, spec)) return fail(error, error_size, out->geterror());
    // OIIO converts float to the file's type (8-bit quantisation with rounding).
    if (!out->write_image(OIIO::TypeDesc::FLOAT, w->pixels)) return fail(error, error_size, out->geterror());
    if (!out->close()) return fail(error, error_size, out->geterror());
    return 0;
  } catch (const std::exception& e) {
    return fail(error, error_size, e.what());
  } catch (...) {
    return fail(error, error_size, "unknown error in the image module");
  }
}

int read_image(const char* path, PdrtImageRead* r, char* error, size_t error_size) {
  try {
    auto in = OIIO::ImageInput::open(path);
    if (!in) return fail(error, error_size, "cannot read image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    float* px = r->alloc(r->context, spec.width, spec.height, spec.nchannels);
    if (!px) return fail(error, error_size, "out of memory for a " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + " image");
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px)) return fail(error, error_size, in->geterror());
    r->integer_format = spec.format == OIIO::TypeDesc::UINT8 || spec.format == OIIO::TypeDesc::UINT16;
    return 0;
  } catch (const std::exception& e) {
    return fail(error, error_size, e.what());
  } catch (...) {
    return fail(error, error_size, "unknown error in the image module");
  }
}

const PdrtImageModule kModule = {PDRT_IMAGE_MODULE_ABI, write_image, read_image};

}  // namespace

extern "C" __attribute__((visibility("default"))) const PdrtImageModule* pdrt_image_module(void) { return &kModule; }
