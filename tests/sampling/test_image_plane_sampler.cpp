// `poisson-ip` (issue 31 item 2): the image-plane pattern's prefixes are Poisson-disk across
// pixel borders and the period's wrap, pixel counts average spp with less spread than
// Poisson's, the shift makes the sample density uniform over seeds, values replay, and
// refusals.
#include "sampling/samplers/image_plane_sampler.h"

#include "sampling/core/errors.h"
#include "sampling/samplers/image_plane_pattern.h"
#include "sampling/samplers/poisson_sampler.h"
#include "tests/support/sampler_points.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace pdrt {
namespace {

std::unique_ptr<Sampler> image_plane(uint64_t seed, int64_t spp, const std::string& base = "poisson") {
  return make_image_plane_sampler(make_sampler(base, seed), SamplerShape{spp, 64, 64}, base + "-ip");
}

// The film points (pixel units) of pixels [x0, x1) x [y0, y1) at `spp`, per pixel.
std::vector<std::vector<std::array<double, 2>>> film_points(const Sampler& s, int x0, int x1, int y0, int y1,
                                                            int64_t spp) {
  std::vector<std::vector<std::array<double, 2>>> px(std::size_t(x1 - x0) * (y1 - y0));
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int64_t j = 0; j < s.samples_in_pixel(x, y, spp); ++j) {
        const Vec2 u = s.get_2d(x, y, j, Family::Pixel, 0);
        px[std::size_t(y - y0) * (x1 - x0) + (x - x0)].push_back({x + u[0], y + u[1]});
      }
  return px;
}

// The smallest distance between film points of the same or 8-neighbouring pixels (brute force
// per pixel pair; the points are closer than a pixel at >= 1 spp).
double min_distance(const std::vector<std::vector<std::array<double, 2>>>& px, int w, int h) {
  double best = 1e30;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int dy = 0; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          if ((dy == 0 && dx < 0) || x + dx < 0 || x + dx >= w || y + dy >= h) continue;
          const auto& a = px[std::size_t(y) * w + x];
          const auto& b = px[std::size_t(y + dy) * w + x + dx];
          for (std::size_t i = 0; i < a.size(); ++i)
            for (std::size_t j = (dx == 0 && dy == 0) ? i + 1 : 0; j < b.size(); ++j)
              best = std::min(best, std::hypot(a[i][0] - b[j][0], a[i][1] - b[j][1]));
        }
  return best;
}

// Hexagonal packing's distance at `spp` points per pixel area (pixels).
double packing_distance(int64_t spp) { return std::sqrt(2.0 / (std::sqrt(3.0) * double(spp))); }

TEST(ImagePlanePattern, PeriodIsTheLargestWhosePrefixFits) {
  EXPECT_EQ(image_plane_period(1), 256);
  EXPECT_EQ(image_plane_period(2), 181);  // 2 * 181^2 = 65522
  EXPECT_EQ(image_plane_period(16), 64);
  EXPECT_EQ(image_plane_period(17), 62);
  EXPECT_EQ(image_plane_period(kImagePlanePoints), 1);
  EXPECT_EQ(image_plane_period(kImagePlanePoints + 1), 0);
  for (int64_t spp = 1; spp <= 4096; spp = spp * 3 + 1) {
    const int64_t P = image_plane_period(spp);
    EXPECT_LE(spp * P * P, kImagePlanePoints);
    EXPECT_GT(spp * (P + 1) * (P + 1), kImagePlanePoints);
  }
}

TEST(ImagePlanePattern, EveryPrefixIsPoissonDiskAtItsRecordedRadius) {
  // Toroidal brute force over the first 2048 points: each point keeps at least the radius in
  // force when it was placed from every earlier point.
  const ImagePlanePattern& p = image_plane_pattern();
  ASSERT_EQ(p.size(), kImagePlanePoints);
  auto torus = [](double d) { return std::min(std::abs(d), 1 - std::abs(d)); };
  for (int i = 1; i < 2048; ++i)
    for (int j = 0; j < i; ++j) {
      const double dx = torus((double(p.coords[2 * i]) - double(p.coords[2 * j])) * 0x1.0p-32);
      const double dy = torus((double(p.coords[2 * i + 1]) - double(p.coords[2 * j + 1])) * 0x1.0p-32);
      ASSERT_GE(std::hypot(dx, dy), p.radius[i] * (1 - 1e-6)) << i << " " << j;
    }
}

TEST(ImagePlaneSampler, NeighbouringPixelsSamplesTogetherArePoissonDiskAcrossBordersAndTheWrap) {
  // Pixels [-2, P + 2)^2 hold the whole period and its wrap on every side: the smallest
  // distance between samples of neighbouring pixels is the prefix's radius (scaled to pixels),
  // and at least 0.6 of hexagonal packing's at that density (McCool–Fiume's relative radius).
  for (int64_t spp : {1, 3, 4, 16}) {  // 3 spp: P = 147, a prefix of 64827 points, not a power of two
    auto s = image_plane(3, spp);
    const int P = image_plane_period(spp), w = P + 4;
    const auto px = film_points(*s, -2, P + 2, -2, P + 2, spp);
    const double d = min_distance(px, w, w);
    const double radius = image_plane_pattern().radius[std::size_t(spp * P * P - 1)] * P;
    EXPECT_GE(d, radius * (1 - 1e-6)) << spp << " spp";
    EXPECT_GE(d / packing_distance(spp), 0.6) << spp << " spp";
  }
}

TEST(ImagePlaneSampler, PerPixelPoissonTablesAreNotPoissonDiskAcrossBordersSoTheTestCanFail) {
  auto s = make_sampler("poisson", 3);
  const auto px = film_points(*s, 0, 32, 0, 32, 4);
  EXPECT_LT(min_distance(px, 32, 32) / packing_distance(4), 0.2);
}

TEST(ImagePlaneSampler, PixelCountsSumToTheSppOverAPeriodAndVaryLessThanPoisson) {
  // Over one period the counts add up to spp * P^2 exactly; over 16 seeds and a 40 x 24 image
  // they average spp within 1 %, and their variance is under 0.4 spp (a Poisson count's is spp).
  for (int64_t spp : {1, 4, 16}) {
    const int P = image_plane_period(spp);
    double sum = 0, sum2 = 0, n = 0;
    for (uint64_t seed = 0; seed < 16; ++seed) {
      auto s = image_plane(seed, spp);
      int64_t period = 0;
      for (int y = 0; y < P; ++y)
        for (int x = 0; x < P; ++x) period += s->samples_in_pixel(x + 5, y - 7, spp);
      ASSERT_EQ(period, spp * P * P);
      for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 40; ++x) {
          const double c = double(s->samples_in_pixel(x, y, spp));
          sum += c, sum2 += c * c, ++n;
        }
    }
    const double mean = sum / n, var = sum2 / n - mean * mean;
    EXPECT_NEAR(mean, double(spp), 0.01 * double(spp)) << spp;
    EXPECT_LT(var, 0.4 * double(spp)) << spp;
  }
}

TEST(ImagePlaneSampler, SampleDensityOverSeedsIsUniformWithinAPixel) {
  // The toroidal shift makes every point uniform over the period: pooled over 2048 seeds, the
  // film points of pixel (3, 5) at 4 spp fill 8 x 8 sub-cells evenly (chi-square, 63 degrees of
  // freedom, below its 0.999 quantile 103.4), and number 4 per pixel per seed within 2 %.
  const int bins = 8, seeds = 2048;
  std::vector<double> count(bins * bins, 0.0);
  double total = 0;
  for (uint64_t seed = 0; seed < seeds; ++seed) {
    auto s = image_plane(seed, 4);
    for (int64_t j = 0; j < s->samples_in_pixel(3, 5, 4); ++j) {
      const Vec2 u = s->get_2d(3, 5, j, Family::Pixel, 0);
      count[std::size_t(int(u[1] * bins) * bins + int(u[0] * bins))] += 1, total += 1;
    }
  }
  EXPECT_NEAR(total / seeds, 4.0, 0.08);
  double chi2 = 0;
  for (double c : count) chi2 += (c - total / (bins * bins)) * (c - total / (bins * bins)) / (total / (bins * bins));
  EXPECT_LT(chi2, 103.4);
}

TEST(ImagePlaneSampler, SamplesInPixelGrowWithSppAndNestPrefixes) {
  // A render from spp a to b takes the pixel's samples [c(a), c(b)): counts never shrink, and
  // the film points of the smaller prefix are the first of the larger one's (pure functions).
  auto s = image_plane(9, 16);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      int64_t last = 0;
      for (int64_t spp : {1, 2, 4, 8, 16}) {
        const int64_t c = s->samples_in_pixel(x, y, spp);
        ASSERT_GE(c, last);
        last = c;
      }
      EXPECT_EQ(s->samples_in_pixel(x, y, 16), s->samples_in_pixel(x + 64, y - 128, 16)) << "period 64";
    }
}

TEST(ImagePlaneSampler, PreparedPixelStreamReadsTheSamplerValuesBitForBit) {
  auto s = image_plane(21, 4);
  for (int x = 0; x < 6; ++x) {
    PreparedStream p;
    p.want = 4;
    s->prepare(x, 2, Family::Pixel, 0, &p);
    ASSERT_TRUE(p.coords);
    ASSERT_GT(p.count, 0u);
    for (uint32_t i = 0; i < p.count; ++i) {
      const Vec2 v = s->get_2d(x, 2, i, Family::Pixel, 0);
      ASSERT_EQ(p.value(i, 0), v[0]);
      ASSERT_EQ(p.value(i, 1), v[1]);
      ASSERT_EQ(s->get_1d(x, 2, i, Family::Pixel, 0), v[0]);
    }
  }
  for (Family f : {Family::Lens, Family::Time, Family::Gloss})
    EXPECT_EQ(test::prepared_mismatches(*s, 4, 3, f, 1, 16), 0) << family_name(f);
}

TEST(ImagePlaneSampler, OtherFamiliesAreTheBaseSamplersAndThePixelOnesAreNot) {
  auto s = image_plane(5, 4);
  auto base = make_sampler("poisson", 5);
  EXPECT_EQ(s->get_2d(2, 3, 1, Family::Lens, 0), base->get_2d(2, 3, 1, Family::Lens, 0));
  EXPECT_EQ(s->get_1d(2, 3, 1, Family::Time, 2), base->get_1d(2, 3, 1, Family::Time, 2));
  EXPECT_EQ(s->get_2d(2, 3, 1, Family::Pixel, 1), base->get_2d(2, 3, 1, Family::Pixel, 1));
  EXPECT_NE(s->get_2d(2, 3, 0, Family::Pixel, 0), base->get_2d(2, 3, 0, Family::Pixel, 0));
  EXPECT_TRUE(s->pixel_counts_vary());
  EXPECT_FALSE(base->pixel_counts_vary());
  EXPECT_EQ(base->samples_in_pixel(2, 3, 7), 7);
}

TEST(ImagePlaneSampler, RefusesMoreSppThanThePatternHasPoints) {
  try {
    image_plane(1, kImagePlanePoints + 1);
    FAIL() << "no refusal";
  } catch (const UsageError& e) {
    EXPECT_STREQ(e.what(),
                 "sampler: \"poisson-ip\" takes at most 65536 spp (the points of its image-plane pattern), got 65537");
  }
  EXPECT_NO_THROW(image_plane(1, kImagePlanePoints));
}

TEST(ImagePlaneSampler, IsBuiltByNameWithTheShapesSpp) {
  auto s = make_sampler("poisson-ip", 4, SamplerShape{16, 32, 32});
  EXPECT_EQ(s->name(), "poisson-ip");
  int64_t period = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) period += s->samples_in_pixel(x, y, 16);
  EXPECT_EQ(period, 16 * 64 * 64);
}

}  // namespace
}  // namespace pdrt
