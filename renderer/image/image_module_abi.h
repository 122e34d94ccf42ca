#pragma once
// The C-linkage function table of the image module (libpdrt_image.so, OpenImageIO inside).
// pdrt loads it with dlopen on the first image read or write, so commands that touch no
// image never load OpenImageIO's ~260 shared libraries (0.5 s and 100 MB per process start).
// Plain C types only: the module and its loader may be built by different compilers' runs.
#include <stddef.h>

extern "C" {

// Bumped whenever a field or a signature below changes.
#define PDRT_IMAGE_MODULE_ABI 3

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

// Image textures through OpenImageIO's TextureSystem (MIP-mapped, filtered, thread-safe).
enum PdrtTextureEncoding { PDRT_ENCODING_AUTO = 0, PDRT_ENCODING_SRGB = 1, PDRT_ENCODING_LINEAR = 2 };
enum PdrtTextureFilter {
  PDRT_FILTER_NONE = 0,
  PDRT_FILTER_BILINEAR = 1,
  PDRT_FILTER_TRILINEAR = 2,
  PDRT_FILTER_EWA = 3
};
enum PdrtTextureWrap { PDRT_WRAP_REPEAT = 0, PDRT_WRAP_CLAMP = 1, PDRT_WRAP_BLACK = 2, PDRT_WRAP_MIRROR = 3 };

struct PdrtTextureOpen {
  const char* path;       // the source image
  const char* cache_dir;  // where the linear, MIP-mapped float copy is kept (created if missing)
  int encoding;           // PdrtTextureEncoding; AUTO: sRGB for 8-bit integer files, else linear
  // Set by texture_open():
  int width, height, channels;  // of the source image
  int srgb;                     // 1 when the texels were decoded from sRGB
};

// One lookup: (s, t) in texture space (t = 0 at the image's top row) with their screen-space
// derivatives, which the MIP filters use and PDRT_FILTER_NONE ignores.
struct PdrtTextureLookup {
  float s, t, dsdx, dtdx, dsdy, dtdy;
  int filter;  // PdrtTextureFilter
  int wrap;    // PdrtTextureWrap
};

// One line of text drawn into (or, with pixels null, only measured for) a caller's image.
struct PdrtImageText {
  float* pixels;  // width * height * 3 display RGB floats, top row first; null: measure only
  int width, height;
  int x, y;          // the left end of the text's baseline, in pixels
  int size;          // the font's size in pixels
  float rgb[3];      // the text's colour
  const char* text;  // one line, UTF-8
  const char* font;  // a font's name or file ("DejaVuSans"); null or "": OpenImageIO's default
  int advance;       // set by draw_text(): the text's width in pixels
};

struct PdrtImageModule {
  int abi;  // PDRT_IMAGE_MODULE_ABI
  // Both return 0 on success; otherwise a one-line message goes to `error` (NUL-terminated,
  // at most `error_size` bytes) and they return nonzero. They never throw.
  int (*write)(const PdrtImageWrite* image, char* error, size_t error_size);
  int (*read)(const char* path, PdrtImageRead* image, char* error, size_t error_size);
  // A private TextureSystem (null on failure, with `error` set); destroy it when done.
  void* (*texture_system_create)(char* error, size_t error_size);
  void (*texture_system_destroy)(void* system);
  // Opens `open->path` as a texture: returns 0 and a handle valid for the system's lifetime.
  int (*texture_open)(void* system, PdrtTextureOpen* open, void** handle, char* error, size_t error_size);
  // Thread-safe; writes RGB (one-channel images replicated). Returns 0, or nonzero and black.
  int (*texture_lookup)(void* system, void* handle, const PdrtTextureLookup* lookup, float rgb[3]);
  // Draws (or measures) one line of text with OpenImageIO's FreeType text; 0, or nonzero with
  // `error` set when no font is found.
  int (*draw_text)(PdrtImageText* text, char* error, size_t error_size);
};

// The module's one exported symbol.
const PdrtImageModule* pdrt_image_module(void);
#define PDRT_IMAGE_MODULE_SYMBOL "pdrt_image_module"
}
