// The image module: reads and writes image files through OpenImageIO behind the C table of
// image_module_abi.h. Built as a CMake MODULE library; the only code in pdrt that links OIIO.
#include "renderer/image/image_module_abi.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/texture.h>

#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
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
    if (!px)
      return fail(error, error_size,
                  "out of memory for a " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + " image");
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px))
      return fail(error, error_size, in->geterror());
    r->integer_format = spec.format == OIIO::TypeDesc::UINT8 || spec.format == OIIO::TypeDesc::UINT16;
    return 0;
  } catch (const std::exception& e) {
    return fail(error, error_size, e.what());
  } catch (...) {
    return fail(error, error_size, "unknown error in the image module");
  }
}

// ---- textures -------------------------------------------------------------------------------

void* texture_system_create(char* error, size_t error_size) {
  try {
    OIIO::TextureSystem* ts = OIIO::TextureSystem::create(/*shared=*/false);
    if (!ts) return fail(error, error_size, "cannot create an OpenImageIO texture system"), nullptr;
    ts->attribute("gray_to_rgb", 1);  // one-channel images look up as grey RGB
    return ts;
  } catch (const std::exception& e) {
    return fail(error, error_size, e.what()), nullptr;
  }
}

void texture_system_destroy(void* system) {
  if (system) OIIO::TextureSystem::destroy(static_cast<OIIO::TextureSystem*>(system));
}

// FNV-1a over the file's bytes: the cache key of its converted copy (with the options).
bool hash_file(const std::string& path, uint64_t* h) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  uint64_t x = 1469598103934665603ull;
  char buf[1 << 16];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    for (std::streamsize i = 0; i < in.gcount(); ++i) x = (x ^ uint8_t(buf[i])) * 1099511628211ull;
    if (!in) break;
  }
  *h = x;
  return true;
}

// Reads every MIP level of the texture into the cache now, when the whole pyramid fits in a
// quarter of the cache with what is already there (pbrt-v4 holds its images whole, too): left
// to load on first use, its tiles (read and inflated one by one) land in whichever pixels touch
// them first, which made the time estimate's scattered calibration blocks 2.5x slower per
// sample than the render on pool-balls at 256 spp. A larger texture still loads on demand.
void preload(OIIO::TextureSystem* ts, OIIO::TextureSystem::TextureHandle* th, const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) return;
  std::vector<OIIO::ImageSpec> levels;
  for (int level = 0; in->seek_subimage(0, level); ++level) levels.push_back(in->spec());
  in->close();
  int64_t bytes = 0;
  for (const OIIO::ImageSpec& l : levels) bytes += int64_t(l.width) * l.height * l.nchannels * int64_t(sizeof(float));
  float max_mb = 0;
  int64_t used = 0;
  if (!ts->getattribute("max_memory_MB", max_mb) || !ts->getattribute("stat:cache_memory_used", OIIO::TypeInt64, &used))
    return;
  if (double(used + bytes) > 0.25 * double(max_mb) * 1024 * 1024) return;
  OIIO::TextureOpt opt;
  std::vector<float> scratch;
  for (std::size_t level = 0; level < levels.size(); ++level) {
    const OIIO::ImageSpec& l = levels[level];
    scratch.resize(std::size_t(l.width) * l.height * l.nchannels);
    // A failure only leaves the tiles to load on demand, where the lookup reports it.
    if (!ts->get_texels(th, nullptr, opt, int(level), 0, l.width, 0, l.height, 0, 1, 0, l.nchannels,
                        OIIO::TypeDesc::FLOAT, scratch.data()))
      return;
  }
}

// pbrt-v4 and Mitsuba 3 decode sRGB before filtering: a MIP level averages linear radiometric
// values, not encoded ones. So every image becomes, once, a tiled, MIP-mapped linear-float
// OpenEXR in the cache (ImageBufAlgo::make_texture), keyed by the file's content and the
// encoding; the TextureSystem then reads only that copy.
int texture_open(void* system, PdrtTextureOpen* o, void** handle, char* error, size_t error_size) {
  namespace fs = std::filesystem;
  try {
    auto* ts = static_cast<OIIO::TextureSystem*>(system);
    auto in = OIIO::ImageInput::open(o->path);
    if (!in) return fail(error, error_size, "cannot read image: " + OIIO::geterror());
    const OIIO::ImageSpec spec = in->spec();
    in->close();
    if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1) return fail(error, error_size, "has no pixels");
    const bool integer = spec.format == OIIO::TypeDesc::UINT8 || spec.format == OIIO::TypeDesc::UINT16 ||
                         spec.format == OIIO::TypeDesc::INT8 || spec.format == OIIO::TypeDesc::INT16;
    const bool srgb = o->encoding == PDRT_ENCODING_SRGB || (o->encoding == PDRT_ENCODING_AUTO && integer);
    o->width = spec.width, o->height = spec.height, o->channels = spec.nchannels, o->srgb = srgb;

    uint64_t h = 0;
    if (!hash_file(o->path, &h)) return fail(error, error_size, "cannot read the image file");
    char name[64];
    std::snprintf(name, sizeof name, "%016llx-%s-v1.exr", static_cast<unsigned long long>(h), srgb ? "srgb" : "linear");
    const fs::path dir = fs::path(o->cache_dir) / "textures";
    const fs::path out = dir / name;
    std::error_code ec;
    if (!fs::exists(out, ec)) {
      fs::create_directories(dir, ec);
      OIIO::ImageBuf src(o->path);
      if (!src.read(0, 0, /*force=*/true, OIIO::TypeDesc::FLOAT)) return fail(error, error_size, src.geterror());
      OIIO::ImageBuf lin;
      if (srgb) {
        if (!OIIO::ImageBufAlgo::colorconvert(lin, src, "sRGB", "linear", /*unpremult=*/false))
          return fail(error, error_size, "sRGB decoding failed: " + lin.geterror());
      } else {
        lin.copy(src);
      }
      OIIO::ImageSpec config;
      config.format = OIIO::TypeDesc::FLOAT;
      config.tile_width = config.tile_height = 64;
      config.attribute("maketx:filtername", "box");  // each level the mean of the one above
      // A unique temporary name, then an atomic rename: parallel renders share the cache.
      static std::atomic<unsigned> counter{0};
      const fs::path tmp =
          dir / (std::string(name) + "." + std::to_string(::getpid()) + "." + std::to_string(counter++) + ".tmp.exr");
      if (!OIIO::ImageBufAlgo::make_texture(OIIO::ImageBufAlgo::MakeTxTexture, lin, tmp.string(), config)) {
        fs::remove(tmp, ec);
        return fail(error, error_size, "cannot write its MIP-mapped copy in " + dir.string() + ": " + OIIO::geterror());
      }
      fs::rename(tmp, out, ec);
      if (ec) {
        fs::remove(tmp, ec);
        if (!fs::exists(out)) return fail(error, error_size, "cannot place its MIP-mapped copy in " + dir.string());
      }
    }
    OIIO::TextureSystem::TextureHandle* th = ts->get_texture_handle(OIIO::ustring(out.string()));
    if (!th || !ts->good(th))
      return fail(error, error_size, "cannot open its MIP-mapped copy " + out.string() + ": " + ts->geterror());
    preload(ts, th, out.string());
    *handle = th;
    return 0;
  } catch (const std::exception& e) {
    return fail(error, error_size, e.what());
  } catch (...) {
    return fail(error, error_size, "unknown error in the image module");
  }
}

OIIO::TextureOpt::Wrap wrap_mode(int w) {
  switch (w) {
    case PDRT_WRAP_CLAMP:
      return OIIO::TextureOpt::WrapClamp;
    case PDRT_WRAP_BLACK:
      return OIIO::TextureOpt::WrapBlack;
    case PDRT_WRAP_MIRROR:
      return OIIO::TextureOpt::WrapMirror;
    default:
      return OIIO::TextureOpt::WrapPeriodic;
  }
}

int texture_lookup(void* system, void* handle, const PdrtTextureLookup* l, float rgb[3]) {
  auto* ts = static_cast<OIIO::TextureSystem*>(system);
  OIIO::TextureOpt opt;
  opt.swrap = opt.twrap = wrap_mode(l->wrap);
  switch (l->filter) {
    case PDRT_FILTER_NONE:  // the nearest texel of the full-resolution image: aliasing shows
      opt.mipmode = OIIO::TextureOpt::MipModeNoMIP, opt.interpmode = OIIO::TextureOpt::InterpClosest;
      break;
    case PDRT_FILTER_BILINEAR:
      opt.mipmode = OIIO::TextureOpt::MipModeNoMIP, opt.interpmode = OIIO::TextureOpt::InterpBilinear;
      break;
    case PDRT_FILTER_TRILINEAR:
      opt.mipmode = OIIO::TextureOpt::MipModeTrilinear, opt.interpmode = OIIO::TextureOpt::InterpBilinear;
      break;
    default:
      opt.mipmode = OIIO::TextureOpt::MipModeAniso, opt.interpmode = OIIO::TextureOpt::InterpBilinear;
      break;
  }
  // The calling thread's own Perthread (OIIO keeps one per thread and frees it at thread exit).
  OIIO::TextureSystem::Perthread* pt = ts->get_perthread_info();
  float out[3] = {0, 0, 0};
  bool ok = ts->texture(static_cast<OIIO::TextureSystem::TextureHandle*>(handle), pt, opt, l->s, l->t, l->dsdx, l->dtdx,
                        l->dsdy, l->dtdy, 3, out);
  for (int c = 0; c < 3; ++c) rgb[c] = ok ? out[c] : 0.0f;
  return ok ? 0 : 1;
}

// ---- text (the labels of the report's sheets) ------------------------------------------------

int draw_text(PdrtImageText* t, char* error, size_t error_size) {
  try {
    const char* font = t->font ? t->font : "";
    const OIIO::ROI box = OIIO::ImageBufAlgo::text_size(t->text, t->size, font);
    if (!box.defined()) return fail(error, error_size, std::string("no font \"") + font + "\": " + OIIO::geterror());
    t->advance = box.xend - box.xbegin;
    if (!t->pixels) return 0;
    OIIO::ImageBuf dst(OIIO::ImageSpec(t->width, t->height, 3, OIIO::TypeDesc::FLOAT), t->pixels);
    if (!OIIO::ImageBufAlgo::render_text(dst, t->x, t->y, t->text, t->size, font, {t->rgb, 3}))
      return fail(error, error_size, dst.geterror());
    return 0;
  } catch (const std::exception& e) {
    return fail(error, error_size, e.what());
  } catch (...) {
    return fail(error, error_size, "unknown error in the image module");
  }
}

const PdrtImageModule kModule = {PDRT_IMAGE_MODULE_ABI,  write_image,  read_image,     texture_system_create,
                                 texture_system_destroy, texture_open, texture_lookup, draw_text};

}  // namespace

extern "C" __attribute__((visibility("default"))) const PdrtImageModule* pdrt_image_module(void) { return &kModule; }
