#pragma once
// The replayable per-pixel sampler (pbrt-v4 style): every value is a pure function of
// (pixel, sample index, dimension family, bounce, seed), so images do not depend on thread
// count or tile order, and raising a pixel from n to m samples only appends samples.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace pdrt {

// The sampled dimensions of distribution ray tracing (Cook 1986 §5).
enum class Family : uint8_t { Pixel = 0, Lens = 1, Time = 2, Light = 3, Gloss = 4 };
inline constexpr int kFamilyCount = 5;
inline constexpr int family_dim(Family f) { return f == Family::Time ? 1 : 2; }
const char* family_name(Family f);

using Vec2 = std::array<double, 2>;

// Hash of a sample's coordinates: the per-(pixel, family, bounce) stream every sampler uses,
// in two steps so samplers mix their seed once.
uint64_t sample_seed_hash(uint64_t seed);
uint64_t sample_stream_from_hash(uint64_t seed_hash, int px, int py, Family family, int bounce);

// A per-stream permutation of sample indices that maps every prefix [0, 2^k) onto itself:
// bit c of the index flips by a hash of the bits above it, except while those are all zero.
// Sequences that are stratified by index (jitter, Sobol) otherwise pair sample i of one
// family with sample i of another through a fixed map, so a pixel's estimate converges to
// the integral along that map instead of over the product domain (a per-pixel bias that
// more samples never remove). Power-of-two prefixes keep their point sets, so their
// stratification and prefix extension are unchanged.
uint64_t shuffle_index(uint64_t index, uint64_t stream);

class Sampler {
 public:
  virtual ~Sampler() = default;
  virtual std::string name() const = 0;
  uint64_t seed() const { return seed_; }

  // Value of sample `index` of pixel (px, py) in `family` at path vertex `bounce`.
  // Pixel-family values are offsets within the pixel, in [0,1)^2.
  virtual double get_1d(int px, int py, int64_t index, Family family, int bounce) const = 0;
  virtual Vec2 get_2d(int px, int py, int64_t index, Family family, int bounce) const = 0;

  // How many samples pixel (px, py) can take before values stop being well distributed
  // (prefix extension is exact below this); unlimited samplers return INT64_MAX.
  virtual int64_t samples_available(int px, int py) const;

 protected:
  explicit Sampler(uint64_t seed) : seed_(seed), seed_hash_(sample_seed_hash(seed)) {}
  // The hash of (pixel, family, bounce) every value of that stream derives from.
  uint64_t stream(int px, int py, Family family, int bounce) const {
    return sample_stream_from_hash(seed_hash_, px, py, family, bounce);
  }
  uint64_t seed_;
  uint64_t seed_hash_;  // mixed once here, not per sample
};

// pbrt-v4's interface on top of the pure functions: one per thread.
class PixelSample {
 public:
  PixelSample(const Sampler& s) : s_(&s) {}
  void start_pixel_sample(int px, int py, int64_t index) { px_ = px, py_ = py, index_ = index; }
  double get_1d(Family f, int bounce = 0) const { return s_->get_1d(px_, py_, index_, f, bounce); }
  Vec2 get_2d(Family f, int bounce = 0) const { return s_->get_2d(px_, py_, index_, f, bounce); }

 private:
  const Sampler* s_;
  int px_ = 0, py_ = 0;
  int64_t index_ = 0;
};

// The sampler names `make_sampler` accepts.
const std::vector<std::string>& sampler_names();

// Throws UsageError naming the sampler for an unknown name.
std::unique_ptr<Sampler> make_sampler(const std::string& name, uint64_t seed);



}  // namespace pdrt
