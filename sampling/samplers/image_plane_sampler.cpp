#include "sampling/samplers/image_plane_sampler.h"

#include "sampling/core/errors.h"
#include "sampling/core/rng.h"
#include "sampling/samplers/image_plane_pattern.h"

#include <algorithm>

namespace pdrt {
namespace {

constexpr double kFixed = 0x1.0p-32;
constexpr uint64_t kShiftSalt = 0x69702d7368696674ull;  // "ip-shift"

class ImagePlaneSampler final : public Sampler {
 public:
  ImagePlaneSampler(std::unique_ptr<Sampler> base, int period, std::string name)
      : Sampler(base->seed()), base_(std::move(base)), name_(std::move(name)), period_(period) {
    bucket(image_plane_pattern());
  }

  std::string name() const override { return name_; }

  double get_1d(int px, int py, int64_t index, Family family, int bounce) const override {
    if (family != Family::Pixel || bounce != 0) return base_->get_1d(px, py, index, family, bounce);
    return get_2d(px, py, index, family, bounce)[0];
  }

  Vec2 get_2d(int px, int py, int64_t index, Family family, int bounce) const override {
    if (family == Family::Pixel && bounce == 0) {
      const uint32_t c = cell(px, py);
      if (index >= 0 && index < int64_t(start_[c + 1] - start_[c])) {
        const std::size_t k = std::size_t(start_[c] + uint32_t(index));
        return {double(offset_[2 * k]) * kFixed, double(offset_[2 * k + 1]) * kFixed};
      }
      // Past the pattern's points in this pixel (only a render of more than the spp the period
      // was chosen for asks): the base sampler's film point, uniform but not Poisson-disk.
    }
    return base_->get_2d(px, py, index, family, bounce);
  }

  void prepare(int px, int py, Family family, int bounce, PreparedStream* out) const override {
    if (family != Family::Pixel || bounce != 0) return base_->prepare(px, py, family, bounce, out);
    // The pixel's offsets are stored in order: the prepared stream reads them in place.
    const uint32_t c = cell(px, py);
    out->coords = offset_.data() + 2 * std::size_t(start_[c]);
    out->base = 0;
    out->count = start_[c + 1] - start_[c];
    out->shift = 1;
    out->grows = false;
    for (int k = 0; k < 2; ++k)
      out->src[k] = uint8_t(k), out->xr[k] = 0, out->add[k] = 0, out->off[k] = 0.0, out->mul[k] = kFixed;
  }
  bool prepare_computes(Family f) const override { return f != Family::Pixel && base_->prepare_computes(f); }

  int64_t samples_available(int px, int py) const override { return base_->samples_available(px, py); }

  // The pixel's points among the first spp * P^2 of the pattern; past the pattern's points, one
  // more per P^2 (the base sampler's film points).
  int64_t samples_in_pixel(int px, int py, int64_t spp) const override {
    const uint32_t c = cell(px, py);
    const int64_t n = spp * int64_t(period_) * period_, points = int64_t(image_plane_pattern().size());
    const uint32_t* first = generation_.data() + start_[c];
    const uint32_t* last = generation_.data() + start_[c + 1];
    if (n <= points) return std::lower_bound(first, last, uint32_t(n)) - first;
    const int64_t cells = int64_t(period_) * period_;
    return (last - first) + (n - points + cells - 1) / cells;
  }
  bool pixel_counts_vary() const override { return true; }

 private:
  uint32_t cell(int px, int py) const {
    const int a = ((px % period_) + period_) % period_, b = ((py % period_) + period_) % period_;
    return uint32_t(b) * uint32_t(period_) + uint32_t(a);
  }

  // One uniform toroidal shift of the whole pattern (32-bit fixed point: the add wraps), then
  // its points grouped by the period's pixel they fall in, generation order kept within each
  // (a counting sort, O(points)), as offsets within the pixel. X = u P is exact in a double
  // (32 + 16 bits), and so is its fraction scaled back to 32 bits.
  void bucket(const ImagePlanePattern& pat) {
    const uint64_t h = mix64(seed_hash_ ^ kShiftSalt);
    const uint32_t shift[2] = {uint32_t(h), uint32_t(h >> 32)};
    const std::size_t n = std::size_t(pat.size()), cells = std::size_t(period_) * period_;
    std::vector<uint32_t> cell_of(n), fixed(2 * n);
    start_.assign(cells + 1, 0);
    for (std::size_t i = 0; i < n; ++i) {
      uint32_t ab[2];
      for (int k = 0; k < 2; ++k) {
        const double X = double(uint32_t(pat.coords[2 * i + k] + shift[k])) * kFixed * period_;
        ab[k] = std::min(uint32_t(X), uint32_t(period_ - 1));
        fixed[2 * i + k] = uint32_t((X - double(ab[k])) * 4294967296.0);
      }
      cell_of[i] = ab[1] * uint32_t(period_) + ab[0];
      ++start_[cell_of[i] + 1];
    }
    for (std::size_t c = 0; c < cells; ++c) start_[c + 1] += start_[c];
    std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
    generation_.resize(n), offset_.resize(2 * n);
    for (std::size_t i = 0; i < n; ++i) {
      const uint32_t k = fill[cell_of[i]]++;
      generation_[k] = uint32_t(i);
      offset_[2 * k] = fixed[2 * i], offset_[2 * k + 1] = fixed[2 * i + 1];
    }
  }

  std::unique_ptr<Sampler> base_;
  std::string name_;
  int period_;
  std::vector<uint32_t> start_;       // cell c's points are [start_[c], start_[c + 1])
  std::vector<uint32_t> generation_;  // their indices in the pattern, increasing within a cell
  std::vector<uint32_t> offset_;      // their offsets within the pixel, fixed point, x then y
};

}  // namespace

std::unique_ptr<Sampler> make_image_plane_sampler(std::unique_ptr<Sampler> base, const SamplerShape& shape,
                                                  std::string name) {
  const int period = image_plane_period(shape.samples_per_pixel);
  if (period == 0)
    throw UsageError("sampler: \"" + name + "\" takes at most " + std::to_string(kImagePlanePoints) +
                     " spp (the points of its image-plane pattern), got " + std::to_string(shape.samples_per_pixel));
  return std::make_unique<ImagePlaneSampler>(std::move(base), period, std::move(name));
}

}  // namespace pdrt
