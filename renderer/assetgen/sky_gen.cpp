// Build-time generator of the procedural sky (procedural_sky.h): writes it as a float EXR
// through the image module, e.g. build/assets/sky.exr.
//   sky_gen OUT.exr
#include "renderer/assetgen/procedural_sky.h"
#include "renderer/image/image_module.h"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: sky_gen OUT.exr\n");
    return 2;
  }
  try {
    const pdrt::SkyParams p;
    const std::vector<float> rgb = pdrt::procedural_sky(p);
    // A fixed date: OpenEXR would otherwise stamp the time of writing (capDate), and the
    // file must be the same bytes on every build.
    const PdrtImageAttribute attrs[] = {{"compression", "zip"}, {"DateTime", "2026:01:01 00:00:00"}};
    PdrtImageWrite w{};
    w.path = argv[1], w.format = "exr";
    w.width = p.width, w.height = p.height, w.channels = 3;
    w.z_channel = -1, w.uint8 = 0;
    w.pixels = rgb.data();
    w.attributes = attrs, w.attribute_count = 2;
    char error[1024] = "";
    if (pdrt::image_module().write(&w, error, sizeof error) != 0) {
      std::fprintf(stderr, "sky_gen: %s\n", error);
      return 1;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sky_gen: %s\n", e.what());
    return 1;
  }
  return 0;
}
