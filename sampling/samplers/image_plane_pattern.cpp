#include "sampling/samplers/image_plane_pattern.h"

#include "sampling/core/cache_dir.h"
#include "sampling/core/checksummed_file.h"
#include "sampling/core/fixed_point.h"
#include "sampling/core/warnings.h"
#include "sampling/generators/generator.h"

#include <cmath>
#include <cstring>
#include <string_view>

namespace pdrt {
namespace {

constexpr char kMagic[8] = {'P', 'D', 'R', 'T', 'I', 'P', 'P', '1'};
constexpr uint64_t kPatternSeed = 0x696d6167652d706cull;  // "image-pl"

ImagePlanePattern generate_pattern() {
  GeneratorParams g;
  g.method = "mccool";
  g.dim = 2;
  g.count = kImagePlanePoints;
  g.periodic = true;  // the pattern tiles the image: prefixes stay Poisson-disk across the wrap
  g.seed = kPatternSeed;
  const PointSet ps = generate(g);
  ImagePlanePattern p;
  p.coords.resize(ps.coords.size());
  for (std::size_t i = 0; i < ps.coords.size(); ++i) p.coords[i] = to_fixed(ps.coords[i]);
  p.radius.assign(ps.radius.begin(), ps.radius.end());
  return p;
}

// The file's body (checksummed_file.h): the coordinates and radii as stored in memory.
std::string payload(const ImagePlanePattern& p) {
  std::string b(p.coords.size() * 4 + p.radius.size() * 4, '\0');
  std::memcpy(b.data(), p.coords.data(), p.coords.size() * 4);
  std::memcpy(b.data() + p.coords.size() * 4, p.radius.data(), p.radius.size() * 4);
  return b;
}

bool read_pattern(const std::filesystem::path& file, ImagePlanePattern* out) {
  const std::size_t n = std::size_t(kImagePlanePoints);
  const auto body = read_checksummed_file(file, std::string_view(kMagic, sizeof kMagic), n * 12);
  if (!body) return false;
  out->coords.resize(2 * n), out->radius.resize(n);
  std::memcpy(out->coords.data(), body->data(), n * 8);
  std::memcpy(out->radius.data(), body->data() + n * 8, n * 4);
  return true;
}

}  // namespace

const ImagePlanePattern& image_plane_pattern() {
  // Generating takes about a second of CPU: the first run keeps it in the cache, as the sample
  // tables; a cache that cannot be written costs one warning, and the next run generates again.
  static const ImagePlanePattern pattern = [] {
    const std::filesystem::path file = cache_dir() / "image-plane-pattern-v1-g1.bin";
    ImagePlanePattern p;
    if (read_pattern(file, &p)) return p;
    p = generate_pattern();
    try {
      write_checksummed_file(file, std::string_view(kMagic, sizeof kMagic), payload(p));
    } catch (const std::exception& e) {
      warn(std::string("pdrt: warning: cannot cache the image-plane pattern (") + e.what() +
           "); using the one generated in memory, which the next run generates again");
    }
    return p;
  }();
  return pattern;
}

int image_plane_period(int64_t spp) {
  if (spp <= 0 || spp > kImagePlanePoints) return 0;
  int64_t P = int64_t(std::sqrt(double(kImagePlanePoints) / double(spp)));
  while (spp * (P + 1) * (P + 1) <= kImagePlanePoints) ++P;  // sqrt's rounding, both ways
  while (P > 0 && spp * P * P > kImagePlanePoints) --P;
  return int(P);
}

}  // namespace pdrt
