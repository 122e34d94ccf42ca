#pragma once
// The C-linkage function table of the image module (libpdrt_image.so, OpenImageIO inside).
// pdrt loads it with dlopen on the first image read or write, so commands that touch no
// image never load OpenImageIO's ~260 shared libraries (0.5 s and 100 MB per process start).
// Plain C types only: the module and its loader may be built by different compilers' runs.
#include <stddef.h>

extern "C" {

// Bumped whenever a field or a signature below changes.
#define PDRT_IMAGE_MODULE_ABI 1

// One string attribute of the image ("pdrt:sampler", "oiio:ColorSpace", "compression", ...).
struct PdrtImageAttribute {
  const char* key;
  const char* value;
};

struct PdrtImageWrite {
  const char* path;    // the file to create
  const char* format;  // the writer's format name: "exr", "png", "jpg", "tif", ...
  int width, height, channels;
  const char* const* channel_names;  // `channels` names, or null for the writer's defaults
  int z_channel;                     // index of the depth channel, or -1
  int uint8;                         // 1: quantise to 8 bits in the file, 0: 32-bit float
  const float* pixels;               // width * height * channels, interleaved, top row first
  const PdrtImageAttribute* attributes;
  int attribute_count;
};

// Filled by read(): `alloc` is called once with the image's size and returns the buffer
// (width * height * channels floats) read() fills.
struct PdrtImageRead {
  void* context;
  float* (*alloc)(void* context, int width, int height, int channels);
  int integer_format;  // set by read(): 1 when the file stores 8- or 16-bit integers (sRGB-encoded)
};

struct PdrtImageModule {
  int abi;  // PDRT_IMAGE_MODULE_ABI
  // Both return 0 on success; otherwise a one-line message goes to `error` (NUL-terminated,
  // at most `error_size` bytes) and they return nonzero. They never throw.
  int (*write)(const PdrtImageWrite* image, char* error, size_t error_size);
  int (*read)(const char* path, PdrtImageRead* image, char* error, size_t error_size);
};

// The module's one exported symbol.
const PdrtImageModule* pdrt_image_module(void);
#define PDRT_IMAGE_MODULE_SYMBOL "pdrt_image_module"
}
