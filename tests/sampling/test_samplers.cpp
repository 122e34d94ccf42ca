// The replayable sampler interface: determinism, stratification, decorrelation.
#include "sampling/samplers/sampler.h"
#include "sampling/measures/elementary_intervals.h"
#include "sampling/analysis/stream_analysis.h"
#include "sampling/samplers/poisson_sampler.h"
#include "sampling/core/rng.h"

#include "tests/support/sampler_points.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <thread>
#include <vector>

namespace pdrt {
namespace {

class EverySampler : public ::testing::TestWithParam<std::string> {
 protected:
  std::unique_ptr<Sampler> s = make_sampler(GetParam(), 42);
};

TEST_P(EverySampler, ValuesInUnitInterval) {
  for (int i = 0; i < 1000; ++i) {
    Vec2 v = s->get_2d(3, 5, i, Family::Lens, 0);
    double t = s->get_1d(3, 5, i, Family::Time, 0);
    ASSERT_TRUE(v[0] >= 0 && v[0] < 1 && v[1] >= 0 && v[1] < 1 && t >= 0 && t < 1);
  }
}

TEST_P(EverySampler, ReplaysInAnyOrderAndFromAnyThread) {
  std::vector<Vec2> forward(256), backward(256), threaded(256);
  for (int i = 0; i < 256; ++i) forward[i] = s->get_2d(7, 9, i, Family::Pixel, 0);
  for (int i = 255; i >= 0; --i) backward[i] = s->get_2d(7, 9, i, Family::Pixel, 0);
  std::thread a([&] {
    for (int i = 0; i < 256; i += 2) threaded[i] = s->get_2d(7, 9, i, Family::Pixel, 0);
  });
  std::thread b([&] {
    for (int i = 1; i < 256; i += 2) threaded[i] = s->get_2d(7, 9, i, Family::Pixel, 0);
  });
  a.join();
  b.join();
  EXPECT_EQ(forward, backward);
  EXPECT_EQ(forward, threaded);
}

// A sampler may keep per-thread caches of what a pixel's streams share (poisson's table
// allocation): two samplers alternating in one thread, and a sampler made where a destroyed
// one lived, must each give what a fresh thread computes.
TEST_P(EverySampler, ThreadCachesServeOnlyTheirSampler) {
  // Each value of `a` then the same of `b` (b may be null), one pixel at a time.
  const auto values = [](const Sampler& a, const Sampler* b) {
    std::vector<double> va, vb;
    for (int px : {4, 5})
      for (int64_t i : {0, 3})
        for (int f = 0; f < kFamilyCount; ++f)
          for (int bounce : {0, 1, 5}) {
            va.push_back(a.get_1d(px, 2, i, Family(f), bounce));
            if (b) vb.push_back(b->get_1d(px, 2, i, Family(f), bounce));
          }
    return std::make_pair(va, vb);
  };
  const auto fresh = [&](const Sampler& x) {
    std::vector<double> v;
    std::thread([&] { v = values(x, nullptr).first; }).join();
    return v;
  };
  auto other = make_sampler(GetParam(), 43);
  const std::vector<double> want_s = fresh(*s), want_other = fresh(*other);
  ASSERT_NE(want_s, want_other);
  const auto got = values(*s, other.get());
  EXPECT_EQ(got.first, want_s);
  EXPECT_EQ(got.second, want_other);
  other.reset();
  auto again = make_sampler(GetParam(), 44);  // often at the address `other` had
  EXPECT_EQ(values(*again, s.get()).first, fresh(*again));
}

// PixelSampleState prepares each stream once per pixel; its values must equal the pure
// functions bit for bit, in any pixel order, for every family and bounce salt (including
// salts past its cache and indices past a table's length).
TEST_P(EverySampler, PixelSampleStateMatchesTheSamplerBitForBit) {
  PixelSampleState ps(*s);
  const int pixels[][2] = {{0, 0}, {5, 3}, {-7, 2}, {300, -41}, {5, 3}, {63, 64}};
  int64_t compared = 0;
  for (const auto& p : pixels)
    for (int64_t i : {0, 1, 2, 15, 16, 63, 255, 1023, 1024, 1500, 5000}) {
      ps.start_pixel_sample(p[0], p[1], i);
      for (int f = 0; f < kFamilyCount; ++f)
        for (int bounce : {0, 1, 7, 31, 32, 40}) {
          Family fam = Family(f);
          if (fam == Family::Time) {
            ASSERT_EQ(s->get_1d(p[0], p[1], i, fam, bounce), ps.get_1d(fam, bounce)) << f << " " << bounce << " " << i;
          } else {
            ASSERT_EQ(s->get_2d(p[0], p[1], i, fam, bounce), ps.get_2d(fam, bounce)) << f << " " << bounce << " " << i;
            ASSERT_EQ(s->get_1d(p[0], p[1], i, fam, bounce), ps.get_1d(fam, bounce)) << f << " " << bounce << " " << i;
          }
          ++compared;
        }
    }
  EXPECT_EQ(compared, 6 * 11 * 5 * 6);
}

// The renderer's passes (set_pixel_pass): dense streams are prepared for the whole pass,
// sparse ones (a deep bounce that few samples reach) are asked value by value, adaptive
// rounds resume at a later begin; every value must still equal the pure function's.
TEST_P(EverySampler, PixelSampleStateInPassesMatchesTheSamplerBitForBit) {
  PixelSampleState ps(*s);
  int64_t compared = 0;
  const int64_t passes[][2] = {{0, 1}, {0, 4}, {0, 64}, {64, 128}, {16, 300}};
  for (int px = -2; px < 3; ++px)
    for (const auto& pass : passes) {
      ps.set_pixel_pass(pass[0], pass[1]);
      for (int64_t i = pass[0]; i < pass[1]; ++i) {
        ps.start_pixel_sample(px, 7, i);
        ASSERT_EQ(s->get_2d(px, 7, i, Family::Pixel, 0), ps.get_2d(Family::Pixel)) << i;
        ASSERT_EQ(s->get_1d(px, 7, i, Family::Time, 0), ps.get_1d(Family::Time, 0)) << i;
        ++compared;
        if (i % 5 == 0) {  // a sparse stream: one sample in five
          ASSERT_EQ(s->get_2d(px, 7, i, Family::Gloss, 9), ps.get_2d(Family::Gloss, 9)) << i;
          ASSERT_EQ(s->get_1d(px, 7, i, Family::Time, 28), ps.get_1d(Family::Time, 28)) << i;
          ++compared;
        }
      }
    }
  EXPECT_GT(compared, 2000);
}

// prepare() for a window [first, want) of a stream (a later pass of a progressive render):
// what it stores starts at or below `first`, reaches `want` when the stream grows, and equals
// the pure functions bit for bit, for windows inside one power-of-two block, across blocks and
// past the tables' 1024 and 2048 points.
TEST_P(EverySampler, PreparedWindowMatchesTheSamplerBitForBit) {
  const uint32_t windows[][2] = {{0, 4}, {4, 8}, {37, 100}, {64, 128}, {1000, 1100}, {1500, 3000}};
  int64_t compared = 0;
  for (const auto& w : windows)
    for (int f = 0; f < kFamilyCount; ++f)
      for (int bounce : {0, 3}) {
        const Family fam = Family(f);
        PreparedStream p;
        p.first = w[0], p.want = w[1];
        s->prepare(-3, 11, fam, bounce, &p);
        if (!p.coords) continue;  // past what the sampler stores: values alone
        ASSERT_LE(p.base, w[0]) << family_name(fam) << " " << w[0];
        if (p.grows) {
          ASSERT_GE(p.count, w[1]) << family_name(fam) << " " << w[0];
        }
        for (uint32_t i = p.base; i < p.count; ++i) {
          if (family_dim(fam) == 1) {
            ASSERT_EQ(p.value(i, 0), s->get_1d(-3, 11, i, fam, bounce)) << family_name(fam) << " " << i;
          } else {
            const Vec2 v = s->get_2d(-3, 11, i, fam, bounce);
            ASSERT_EQ(p.value(i, 0), v[0]) << family_name(fam) << " " << i;
            ASSERT_EQ(p.value(i, 1), v[1]) << family_name(fam) << " " << i;
          }
          ++compared;
        }
      }
  EXPECT_GT(compared, 6 * 2 * 4 * 4);  // every window of at least the 2-D families
}

TEST_P(EverySampler, BouncesAndSeedsDrawDifferentValues) {
  auto other_seed = make_sampler(GetParam(), 43);
  int same_bounce = 0, same_seed = 0;
  for (int i = 0; i < 64; ++i) {
    Vec2 v = s->get_2d(1, 1, i, Family::Gloss, 0);
    same_bounce += v == s->get_2d(1, 1, i, Family::Gloss, 1);
    same_seed += v == other_seed->get_2d(1, 1, i, Family::Gloss, 0);
  }
  EXPECT_EQ(same_bounce, 0);
  EXPECT_EQ(same_seed, 0);
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  double n = double(a.size()), ma = 0, mb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) ma += a[i] / n, mb += b[i] / n;
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return sab / std::sqrt(saa * sbb);
}

TEST_P(EverySampler, FamiliesAreDecorrelatedAcrossPixels) {
  // Cook §5.1: each dimension gets its own prototype pattern. Over 10^4 pixels and their
  // first 4 samples (4x10^4 pairs, standard error of r = 0.005), lens vs pixel and time vs
  // lens coordinates must be uncorrelated: |r| < 0.02, four standard errors.
  std::vector<double> pix, lens, time;
  for (int64_t index = 0; index < 4; ++index)
    for (int py = 0; py < 100; ++py)
      for (int px = 0; px < 100; ++px) {
        pix.push_back(s->get_2d(px, py, index, Family::Pixel, 0)[0]);
        lens.push_back(s->get_2d(px, py, index, Family::Lens, 0)[0]);
        time.push_back(s->get_1d(px, py, index, Family::Time, 0));
      }
  EXPECT_LT(std::abs(correlation(lens, pix)), 0.02);
  EXPECT_LT(std::abs(correlation(time, lens)), 0.02);
}

INSTANTIATE_TEST_SUITE_P(Samplers, EverySampler, ::testing::ValuesIn(sampler_names()));
// poisson-ip renders only by splatting, so sampler_names() leaves it out; as a sampler it is one of them.
INSTANTIATE_TEST_SUITE_P(ImagePlane, EverySampler, ::testing::Values(std::string("poisson-ip")));

// The index shuffle permutes [2^t, 2^(t+1)) within itself (so every power-of-two prefix keeps
// its point set), its bulk form equals the per-index one, and it depends on the stream.
TEST(IndexShuffle, PermutesEveryPowerOfTwoBlockAndFillMatches) {
  for (uint64_t stream : {1ull, 0x123456789abcdefull}) {
    const IndexShuffle shuffle(stream);
    const uint32_t n = 5000;
    std::vector<uint32_t> bulk(n);
    shuffle.fill(0, n, bulk.data());
    std::vector<bool> seen(8192, false);
    for (uint32_t i = 0; i < 8192; ++i) {
      const uint64_t j = shuffle(i);
      if (i < n) {
        ASSERT_EQ(j, bulk[i]) << i;
      }
      if (i < 2) {
        ASSERT_EQ(j, i);
      } else {
        ASSERT_EQ(j >> (63 - __builtin_clzll(i)), 1u) << i;  // stays in its block
      }
      ASSERT_FALSE(seen[j]) << i;
      seen[j] = true;
    }
  }
  // A window [first, n) equals the same indices of the whole fill.
  const IndexShuffle shuffle(7);
  std::vector<uint32_t> whole(3000), window(3000);
  shuffle.fill(0, 3000, whole.data());
  for (uint32_t first : {0u, 1u, 2u, 3u, 37u, 64u, 1500u, 2999u}) {
    shuffle.fill(first, 3000, window.data());
    for (uint32_t i = first; i < 3000; ++i) ASSERT_EQ(window[i - first], whole[i]) << first << " " << i;
  }
  int same = 0;
  for (uint64_t i = 2; i < 1024; ++i) same += IndexShuffle(1)(i) == IndexShuffle(2)(i);
  EXPECT_LT(same, 100);  // about 1022 * (mean 1 / block size) by chance, i.e. about 10
}

// The flips are a nested scramble with independent bits: over many streams, sample i's
// shuffled index is uniform over its block (chi-square, 16 cells, 99.9 % critical 37.7).
TEST(IndexShuffle, ShuffledIndexIsUniformOverStreams) {
  for (uint64_t i : {16u, 21u, 31u}) {
    std::vector<int> count(16, 0);
    const int streams = 16000;
    for (int s = 0; s < streams; ++s) ++count[IndexShuffle(mix64(uint64_t(s)))(i) - 16];
    double chi2 = 0;
    for (int c : count) chi2 += (c - 1000.0) * (c - 1000.0) / 1000.0;
    EXPECT_LT(chi2, 37.7) << i;
  }
}

// Counts of the first n 2-D samples of one pixel in a gx x gy grid of strata.
std::vector<int> strata(const Sampler& s, int n, int gx, int gy) {
  std::vector<int> hits(gx * gy, 0);
  for (int i = 0; i < n; ++i) {
    Vec2 v = s.get_2d(2, 3, i, Family::Light, 0);
    ++hits[int(v[1] * gy) * gx + int(v[0] * gx)];
  }
  return hits;
}

TEST(ProgressiveJitterSampler, PowerOfFourPrefixesAreKByKStratified) {
  auto s = make_sampler("jitter", 9);
  for (int k : {1, 2, 4, 8, 16}) {
    auto hits = strata(*s, k * k, k, k);
    EXPECT_TRUE(std::all_of(hits.begin(), hits.end(), [](int h) { return h == 1; })) << k << "x" << k;
  }
}

TEST(ProgressiveJitterSampler, PowerOfTwoTimePrefixesAreStratified) {
  auto s = make_sampler("jitter", 9);
  for (int n : {2, 8, 64}) {
    std::vector<int> hits(n, 0);
    for (int i = 0; i < n; ++i) ++hits[int(s->get_1d(4, 4, i, Family::Time, 0) * n)];
    EXPECT_TRUE(std::all_of(hits.begin(), hits.end(), [](int h) { return h == 1; })) << n;
  }
}

TEST(SobolSampler, PowerOfTwoPrefixesAreZeroTwoNets) {
  // Owen scrambling keeps the (0,2)-net property: 2^m points fill every elementary interval
  // of area 2^-m exactly once, for every split 2^a x 2^(m-a).
  auto s = make_sampler("sobol", 9);
  for (int m : {4, 6, 8})
    for (int a = 0; a <= m; ++a) {
      auto hits = strata(*s, 1 << m, 1 << a, 1 << (m - a));
      EXPECT_TRUE(std::all_of(hits.begin(), hits.end(), [](int h) { return h == 1; })) << m << " " << a;
    }
}

// RMS error over 64 x 32 pixels of estimating the time a moving edge has covered a pixel,
// the integral of [t < tau] = tau, from each pixel's first n time samples.
double time_step_rmse(const Sampler& s, int n) {
  double sum = 0;
  int pixels = 0;
  for (int py = 0; py < 32; ++py)
    for (int px = 0; px < 64; ++px, ++pixels) {
      const double tau = (px + 0.37 * py / 32.0 + 0.5) / 64.4;
      int hits = 0;
      for (int i = 0; i < n; ++i) hits += s.get_1d(px, py, i, Family::Time, 0) < tau;
      sum += (double(hits) / n - tau) * (double(hits) / n - tau);
    }
  return std::sqrt(sum / pixels);
}

TEST(PoissonSampler, TimeSamplesIntegrateAStepFarBetterThanRandomAtEveryCount) {
  // The 1-D time tables must be uniform as well as Poisson-disk. Relaxation tables with
  // uneven density (Kuiper discrepancy ~0.08) matched random's error by 1024 samples
  // (docs/results.md); poisson-065's balanced ones measure 5.1x / 5.7x / 9.2x below it at
  // 64 / 256 / 1024 samples, poisson's stratified ones far more.
  for (const char* name : {"poisson", "poisson-065"}) {
    auto poisson = make_sampler(name, 5), random = make_sampler("random", 5);
    for (int n : {64, 256, 1024}) {
      const double p = time_step_rmse(*poisson, n), r = time_step_rmse(*random, n);
      EXPECT_LT(p, r / 3) << n << " samples: " << name << " " << p << ", random " << r;
    }
  }
}

}  // namespace
}  // namespace pdrt

namespace pdrt {
namespace {

// poisson randomises by symmetries and digital (xor) shifts, which map elementary intervals
// onto elementary intervals: every power-of-two prefix of every stream a render reads stays a
// (0,m,2)-net, and every 2^k prefix of a time stream one point per 1/2^k stratum. (A
// toroidal shift would cut the strata at the seam.) The isometric shift keeps them too.
TEST(PoissonSampler, EveryStreamKeepsItsStrata) {
  auto s = make_sampler("poisson", 11);
  const PoissonShift iso = PoissonShift::Isometric;
  auto isometric = make_poisson_sampler(11, default_tables(), {.plane = iso, .pixel = iso, .time = iso});
  for (const Sampler* smp : {s.get(), isometric.get()})
    for (auto [px, py] : {std::pair{0, 0}, std::pair{-7, 123}, std::pair{40000, 3}})
      for (auto [f, bounce] : {std::pair{Family::Pixel, 0}, std::pair{Family::Lens, 0}, std::pair{Family::Light, 5},
                               std::pair{Family::Gloss, 15}}) {
        const PointSet ps = test::stream_points(*smp, {{px, py}}, 1024, f, bounce);
        for (std::size_t n = 1; n <= 1024; n *= 2)
          ASSERT_TRUE(is_02_net(ps, 0, n)) << family_name(f) << " pixel " << px << "," << py << " n " << n;
      }
  for (int bounce : {0, 48}) {
    for (uint64_t n = 1; n <= 2048; n *= 2) {
      std::vector<int> hits(n, 0);
      for (uint64_t i = 0; i < n; ++i)
        ++hits[std::size_t(s->get_1d(9, 9, int64_t(i), Family::Time, bounce) * double(n))];
      ASSERT_TRUE(std::all_of(hits.begin(), hits.end(), [](int h) { return h == 1; })) << bounce << " " << n;
    }
  }
}

TEST(PoissonSampler, IsNamedForItsTableSet) {
  EXPECT_EQ(make_sampler("poisson", 1)->name(), "poisson");
  EXPECT_EQ(make_sampler("poisson-065", 1)->name(), "poisson-065");
}

// The isometric shift keeps the tables' distances (issue 28): on the torus, every
// power-of-two prefix of the 2-D streams keeps rho >= 0.35 in every pixel (measured min
// 0.40-0.44 over 64 pixels; the tables' own prefixes 0.39-0.42 at worst). The default digital
// shift of every bit leaves 0.13 at 16 points and 0.05 at 256 in the worst pixel (Sobol's
// level): the test sees the difference.
TEST(PoissonSampler, IsometricShiftKeepsTheTablesDistancesInRenderTimeStreams) {
  for (const bool full_digital : {false, true}) {
    const PoissonShift shift = full_digital ? PoissonShift::Digital : PoissonShift::Isometric;
    auto s = make_poisson_sampler(7, default_tables(), {.plane = shift, .pixel = shift});
    double worst = 1;
    for (Family f : {Family::Pixel, Family::Lens, Family::Light, Family::Gloss})
      for (int n : {16, 64, 256}) {
        const StreamAnalysis a = analyze_stream(*s, f, 64, 64, n, 64);
        if (!full_digital) {
          EXPECT_GE(a.rho_min, 0.35) << family_name(f) << " " << n;
        }
        worst = std::min(worst, a.rho_min);
      }
    if (full_digital) {
      EXPECT_LT(worst, 0.2);
    }
  }
}

}  // namespace
}  // namespace pdrt

namespace pdrt {
namespace {

// Two time streams of one pixel (the shutter and a vertex's decisions) must not visit their
// strata in lockstep. The stratified-bc tables share progressive jitter's parent order, so
// their 16-prefixes' strata differ by a constant xor, which a digital shift keeps: without
// the per-stream index shuffle, 63 of the 120 pairs below did (and gloss-translucency at
// 256 spp rendered 10 % worse than Sobol, 0.0300 against 0.0272 at 160 x 120).
TEST(PoissonSampler, TimeStreamsOfAPixelDoNotMoveInLockstep) {
  auto s = make_sampler("poisson", 3);
  int lockstep = 0, pairs = 0;
  for (int px = 0; px < 8; ++px)
    for (int a = 0; a < 6; ++a)
      for (int b = a + 1; b < 6; ++b, ++pairs) {
        std::set<int> xors;
        for (int i = 0; i < 16; ++i)
          xors.insert(int(s->get_1d(px, 1, i, Family::Time, a) * 16) ^ int(s->get_1d(px, 1, i, Family::Time, b) * 16));
        lockstep += xors.size() == 1;
      }
  EXPECT_EQ(lockstep, 0) << "of " << pairs << " pairs";
}

}  // namespace
}  // namespace pdrt

namespace pdrt {

// `regular` (Cook's baseline): the same points in every pixel, bounce and seed; sample 0 at the
// pixel centre; the first 4^k samples a lattice of 2^k x 2^k points one per cell (a (0,2)-net
// shifted by 1/2 keeps one point per square of side 2^-k); prepare() matches get_2d bit for bit.
TEST(RegularSampler, SamePointsEverywhereCentreFirstAndEachPowerOfFourPrefixOnePerCell) {
  auto a = make_sampler("regular", 1), b = make_sampler("regular", 99);
  EXPECT_EQ(a->get_2d(3, 4, 0, Family::Pixel, 0), (Vec2{0.5, 0.5}));
  for (int64_t i = 0; i < 64; ++i) {
    EXPECT_EQ(a->get_2d(3, 4, i, Family::Pixel, 0), b->get_2d(1000, -7, i, Family::Gloss, 15)) << i;
    EXPECT_EQ(a->get_1d(0, 0, i, Family::Time, 0), a->get_2d(5, 5, i, Family::Lens, 2)[0]) << i;
  }
  for (int k = 0; k <= 4; ++k) {
    const int side = 1 << k;
    std::vector<int> cells(std::size_t(side) * side, 0);
    for (int64_t i = 0; i < int64_t(side) * side; ++i) {
      Vec2 p = a->get_2d(0, 0, i, Family::Pixel, 0);
      ++cells[std::size_t(int(p[1] * side)) * side + int(p[0] * side)];
    }
    for (int c : cells) EXPECT_EQ(c, 1) << "prefix 4^" << k;
  }
  PreparedStream s;
  s.want = 64;
  a->prepare(2, 2, Family::Pixel, 0, &s);
  ASSERT_NE(s.coords, nullptr);
  for (int64_t i = 0; i < 64; ++i) EXPECT_EQ(s.value(i, 1), a->get_2d(2, 2, i, Family::Pixel, 0)[1]) << i;
}

}  // namespace pdrt
