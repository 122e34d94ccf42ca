// Point-set analysis library and `pdrt analyze`.
#include "sampling/analysis/analysis_report.h"
#include "sampling/analysis/chi_square.h"
#include "sampling/analysis/discrepancy.h"
#include "sampling/core/distance.h"
#include "sampling/generators/generator.h"
#include "sampling/analysis/incomplete_gamma.h"
#include "sampling/analysis/max_empty_ball.h"
#include "sampling/measures/min_distance.h"
#include "sampling/analysis/periodogram.h"
#include "sampling/analysis/radial_spectrum.h"
#include "sampling/core/rng.h"

#include "tests/support/cli_runner.h"

#include "tests/support/point_checks.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace pdrt;

namespace {

PointSet random_points(std::size_t n, int dim, uint64_t seed) {
  PointSet ps;
  ps.dim = dim;
  Rng rng(seed);
  for (std::size_t i = 0; i < n * dim; ++i) ps.coords.push_back(rng.uniform());
  return ps;
}

// Regular k^dim grid at offset `offset` (in cells): points at (i + offset) / k.
PointSet grid_points(int k, int dim, double offset) {
  PointSet ps;
  ps.dim = dim;
  std::size_t total = 1;
  for (int d = 0; d < dim; ++d) total *= std::size_t(k);
  for (std::size_t idx = 0; idx < total; ++idx) {
    std::size_t t = idx;
    for (int d = 0; d < dim; ++d) {
      ps.coords.push_back((double(t % k) + offset) / k);
      t /= k;
    }
  }
  return ps;
}

// ---- CLI helpers

using test::run_pdrt;
using test::scratch_dir;

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

std::string csv_of(const PointSet& ps, bool with_radius = false, double radius = 0.0) {
  std::ostringstream s;
  s.precision(9);
  for (int k = 0; k < ps.dim; ++k) s << (k ? ",x" : "x") << k;
  if (with_radius) s << ",radius";
  s << '\n';
  for (std::size_t i = 0; i < ps.size(); ++i) {
    for (int k = 0; k < ps.dim; ++k) s << (k ? "," : "") << ps.point(i)[k];
    if (with_radius) s << ',' << radius;
    s << '\n';
  }
  return s.str();
}

bool is_png(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  char sig[8] = {};
  in.read(sig, 8);
  return in && std::string(sig + 1, 3) == "PNG" && fs::file_size(path) > 1000;
}

// Runs `pdrt analyze` on a bad file and checks: exit 1, one stderr line naming file:line,
// and no stats.json.
void expect_rejected(const std::string& name, const std::string& content, const std::string& where) {
  fs::path dir = scratch_dir(name);
  fs::path csv = dir / (name + ".csv");
  write_text(csv, content);
  fs::path out = dir / "out";
  test::CliResult r = run_pdrt("analyze '" + csv.string() + "' --no-plots --out '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find(csv.string() + ":" + where), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(out / "stats.json"));
}

}  // namespace

// ---- min distance and relative radius

TEST(Analysis, PeriodicDiscrepancyOfALatticeIsOneOverN) {
  std::vector<double> x;
  for (int i = 0; i < 100; ++i) x.push_back((i + 0.5) / 100);
  EXPECT_NEAR(periodic_discrepancy_1d(x), 0.01, 1e-12);
  for (double& v : x) v = v + 0.37 - std::floor(v + 0.37);  // rotating the circle changes nothing
  EXPECT_NEAR(periodic_discrepancy_1d(x), 0.01, 1e-12);
}

TEST(Analysis, PeriodicDiscrepancySeesAHalfEmptyCircle) {
  std::vector<double> x;
  for (int i = 0; i < 100; ++i) x.push_back((i + 0.5) / 200);  // all in [0, 1/2)
  EXPECT_NEAR(periodic_discrepancy_1d(x), 0.5 + 0.005, 1e-12);
  EXPECT_EQ(periodic_discrepancy_1d({}), 0.0);
}

TEST(Analysis, MinDistanceMatchesBruteForceBounded) {
  for (int dim : {1, 2, 3, 5}) {
    PointSet ps = random_points(700, dim, 11 + dim);
    EXPECT_DOUBLE_EQ(min_distance(ps, false), test::brute_min_distance(ps, ps.size(), false)) << "dim " << dim;
  }
}

TEST(Analysis, MinDistanceMatchesBruteForcePeriodic) {
  for (int dim : {1, 2, 3, 5}) {
    PointSet ps = random_points(300, dim, 21 + dim);
    // A pair across the x0 = 0 seam, closer through the wrap than any other pair.
    std::vector<double> a(dim, 0.5), b(dim, 0.5);
    a[0] = 1e-7, b[0] = 1.0 - 1e-7;
    ps.coords.insert(ps.coords.end(), a.begin(), a.end());
    ps.coords.insert(ps.coords.end(), b.begin(), b.end());
    double expect = test::brute_min_distance(ps, ps.size(), true);
    EXPECT_DOUBLE_EQ(min_distance(ps, true), expect) << "dim " << dim;
    EXPECT_NEAR(expect, 2e-7, 1e-12);
    EXPECT_GT(min_distance(ps, false), expect);
  }
}

TEST(Analysis, MinDistanceOfOnePointIsInfinite) {
  EXPECT_TRUE(std::isinf(min_distance(random_points(1, 2, 1), false)));
}

TEST(Analysis, PrefixRelativeRadiusMatchesBruteForce) {
  for (bool periodic : {false, true}) {
    PointSet ps = random_points(250, 2, 5);
    std::vector<double> rho = prefix_relative_radius(ps, periodic);
    ASSERT_EQ(rho.size(), ps.size() - 1);
    for (std::size_t n = 2; n <= ps.size(); ++n)
      EXPECT_DOUBLE_EQ(rho[n - 2], test::brute_min_distance(ps, n, periodic) / max_packing_distance(int64_t(n), 2))
          << "n " << n << " periodic " << periodic;
    EXPECT_DOUBLE_EQ(rho.back(), relative_radius(min_distance(ps, periodic), ps.size(), 2));
  }
}

// ---- coverage (largest empty ball)

TEST(Analysis, MaxEmptyRadiusOfRegularGrid2DMatchesAnalytic) {
  const int k = 10;
  // Cell-centred grid: holes at the cell corners, half a cell diagonal from the nearest points.
  PointSet centred = grid_points(k, 2, 0.5);
  EXPECT_NEAR(max_empty_ball(centred, true).radius, std::sqrt(2.0) / (2 * k), 1e-12);
  EXPECT_NEAR(max_empty_ball(centred, false).radius, std::sqrt(2.0) / (2 * k), 1e-12);
  // Corner-aligned grid, bounded: the far corner (1,1) is a whole cell diagonal from (k-1)/k.
  PointSet aligned = grid_points(k, 2, 0.0);
  EmptyBall b = max_empty_ball(aligned, false);
  EXPECT_NEAR(b.radius, std::sqrt(2.0) / k, 1e-12);
  EXPECT_NEAR(b.center[0], 1.0, 1e-12);
  EXPECT_NEAR(b.center[1], 1.0, 1e-12);
  EXPECT_TRUE(b.exact);
  EXPECT_NEAR(max_empty_ball(aligned, true).radius, std::sqrt(2.0) / (2 * k), 1e-12);
}

TEST(Analysis, MaxEmptyRadiusOfRegularGrid3DMatchesAnalytic) {
  const int k = 5;
  PointSet centred = grid_points(k, 3, 0.5);
  EXPECT_NEAR(max_empty_ball(centred, true).radius, std::sqrt(3.0) / (2 * k), 1e-7);
  EXPECT_NEAR(max_empty_ball(grid_points(k, 3, 0.0), false).radius, std::sqrt(3.0) / k, 1e-7);
}

TEST(Analysis, MaxEmptyRadiusIsAtLeastEveryProbedDistance) {
  // The exact 2-D answer bounds a dense grid search from above, and not by much.
  for (bool periodic : {false, true}) {
    PointSet ps = random_points(60, 2, 9);
    double probe_best = 0.0;
    const int G = 400;
    for (int i = 0; i <= G; ++i)
      for (int j = 0; j <= G; ++j) {
        double q[2] = {double(i) / G, double(j) / G};
        double m = std::numeric_limits<double>::infinity();
        for (std::size_t p = 0; p < ps.size(); ++p) m = std::min(m, distance_sq(q, &ps.coords[2 * p], 2, periodic));
        probe_best = std::max(probe_best, std::sqrt(m));
      }
    double exact = max_empty_ball(ps, periodic).radius;
    EXPECT_GE(exact, probe_best - 1e-12);
    EXPECT_LE(exact, probe_best + std::sqrt(2.0) / G);
  }
}

TEST(Analysis, MaxEmptyRadius1DIsHalfTheLargestGap) {
  PointSet ps;
  ps.dim = 1;
  ps.coords = {0.1, 0.3, 0.8};
  EXPECT_NEAR(max_empty_ball(ps, false).radius, 0.25, 1e-15);  // gap 0.3..0.8
  ps.coords = {0.3, 0.45, 0.6};
  EXPECT_NEAR(max_empty_ball(ps, false).radius, 0.4, 1e-15);  // the end x = 1
  EXPECT_NEAR(max_empty_ball(ps, true).radius, 0.35, 1e-15);  // wrap gap 0.6..1.3
}

// ---- chi-square uniformity

TEST(Analysis, IncompleteGammaMatchesClosedForms) {
  for (double x : {0.01, 0.5, 1.0, 3.0, 10.0, 40.0}) {
    EXPECT_NEAR(regularized_gamma_q(1.0, x), std::exp(-x), 1e-14 * std::max(1.0, std::exp(-x)) + 1e-300);
    EXPECT_NEAR(regularized_gamma_q(0.5, x) / std::erfc(std::sqrt(x)), 1.0, 1e-12);
    // Integer a: Q(a, x) = e^-x sum_{i<a} x^i / i!.
    double term = 1.0, sum = 1.0;
    for (int i = 1; i < 7; ++i) sum += term *= x / i;
    EXPECT_NEAR(regularized_gamma_q(7.0, x) / (std::exp(-x) * sum), 1.0, 1e-12);
    EXPECT_NEAR(regularized_gamma_p(7.0, x) + regularized_gamma_q(7.0, x), 1.0, 1e-14);
  }
  // Large dof: the mean k lies just above the median, Wilson–Hilferty gives
  // p = 1 - Phi(sqrt(2 / 9k)) = 0.49867 for k = 20000.
  EXPECT_NEAR(chi_square_p_value(20000.0, 20000.0), 0.5 - 0.5 * std::erf(std::sqrt(2.0 / 180000.0) / std::sqrt(2.0)),
              1e-5);
}

TEST(Analysis, ChiSquareOfUniformPointsIsNotTiny) {
  ChiSquare c = chi_square_uniformity(random_points(20000, 2, 3));
  ASSERT_TRUE(c.valid);
  EXPECT_GE(c.expected, 5.0);
  EXPECT_GT(c.p, 1e-3);
}

TEST(Analysis, ChiSquareOfClumpedPointsIsTiny) {
  // Three quarters of the points squeezed into the lower-left quarter of the square.
  PointSet ps = random_points(20000, 2, 4);
  for (std::size_t i = 0; i < ps.size(); i += 4)
    for (int k = 0; k < 2; ++k) ps.coords[2 * i + k] *= 0.5;
  for (std::size_t i = 1; i < ps.size(); i += 4)
    for (int k = 0; k < 2; ++k) ps.coords[2 * i + k] *= 0.5;
  ChiSquare c = chi_square_uniformity(ps);
  ASSERT_TRUE(c.valid);
  EXPECT_LT(c.p, 1e-10);
}

// ---- periodogram

TEST(Analysis, PeriodogramOfUniformPointsHasUnitRadialPower) {
  // K realizations of N uniform points: every k != 0 has expected power exactly 1 (0 dB).
  const int K = 8, N = 4096, R = 128;
  std::vector<PointSet> sets;
  for (int s = 0; s < K; ++s) sets.push_back(random_points(N, 2, 100 + s));
  Periodogram pg = compute_periodogram(sets, R);
  EXPECT_EQ(pg.realizations, K);
  EXPECT_EQ(pg.at(0, 0), 0.0);  // DC removed
  RadialSpectrum rs = equal_annuli(pg, 20);
  ASSERT_EQ(rs.power.size(), 20u);
  double total = 0.0;
  int64_t pixels = 0;
  for (std::size_t i = 0; i < rs.power.size(); ++i) {
    // Each value is exponential with mean 1; F(-k) = conj F(k) halves the independent ones.
    // Tolerance: 4 standard errors of the annulus mean.
    double sigma = 1.0 / std::sqrt(0.5 * double(rs.pixels[i]) * K);
    EXPECT_NEAR(rs.power[i], 1.0, 4.0 * sigma) << "annulus " << i;
    total += rs.power[i] * double(rs.pixels[i]);
    pixels += rs.pixels[i];
  }
  // Over the whole plane: within 0.1 dB of 0 dB.
  EXPECT_NEAR(to_db(total / double(pixels)), 0.0, 0.1);
  // White-noise anisotropy of a K-average is about 1/K (-10 log10 K dB).
  RadialSpectrum fine = fine_annuli(pg);
  double mean_aniso = 0.0;
  for (std::size_t i = 10; i < fine.anisotropy.size(); ++i) mean_aniso += fine.anisotropy[i];
  mean_aniso /= double(fine.anisotropy.size() - 10);
  EXPECT_NEAR(to_db(mean_aniso), -10.0 * std::log10(double(K)), 1.0);
}

TEST(Analysis, OneDimensionalPeriodogramOfUniformPointsIsFlat) {
  std::vector<PointSet> sets;
  for (int s = 0; s < 4; ++s) sets.push_back(random_points(2000, 1, 300 + s));
  Periodogram pg = compute_periodogram(sets, 8192);
  EXPECT_EQ(pg.spectral_dim, 1);
  RadialSpectrum rs = equal_annuli(pg, 20);
  for (std::size_t i = 0; i < rs.power.size(); ++i) EXPECT_NEAR(to_db(rs.power[i]), 0.0, 1.0) << "annulus " << i;
}

TEST(Analysis, DefaultResolutionIsMcCoolsForSixtyFourPoints) {
  EXPECT_EQ(default_periodogram_resolution(2, 64), 32);  // McCool & Fiume §2: 64 impulses, 32×32
  EXPECT_EQ(default_periodogram_resolution(2, 1e4), 512);
  EXPECT_EQ(default_periodogram_resolution(2, 1e9), max_periodogram_resolution(2));
}

// ---- the `pdrt analyze` command

TEST(AnalyzeCli, WritesStatsJsonAndPlots) {
  fs::path dir = scratch_dir("good");
  fs::path csv = dir / "points.csv";
  write_text(csv, csv_of(random_points(1500, 2, 77), true, 0.01));
  fs::path out = dir / "out" / "nested";  // created if missing
  test::CliResult r = run_pdrt("analyze '" + csv.string() + "' --periodic --quiet --out '" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // --quiet: the created directory is the only line.
  EXPECT_EQ(r.err, "pdrt: created directory '" + (dir / "out").string() + "' for '" + out.string() + "'\n");
  std::ifstream in(out / "stats.json");
  nlohmann::json s = nlohmann::json::parse(in);
  for (const char* key : {"count", "dim", "min_distance", "relative_radius", "max_empty_radius", "chi2_p",
                          "prefix_relative_radius", "realizations", "periodic", "per_file", "spectrum"})
    EXPECT_TRUE(s.contains(key)) << key;
  EXPECT_EQ(s["count"], 1500);
  EXPECT_EQ(s["dim"], 2);
  EXPECT_EQ(s["periodic"], true);
  EXPECT_EQ(s["realizations"], 1);
  EXPECT_EQ(s["prefix_relative_radius"].size(), 1499u);
  EXPECT_EQ(s["disk_radius"], 0.01);
  for (const char* group : {"annuli", "fine_annuli"})
    for (const char* key : {"frequency", "frequency_normalized", "power", "power_db", "anisotropy", "anisotropy_db"})
      EXPECT_TRUE(s["spectrum"][group][key].is_array()) << group << "." << key;
  EXPECT_EQ(s["spectrum"]["annuli"]["power_db"].size(), 20u);
  for (const char* png : {"points.png", "periodogram.png", "radial_power.png", "anisotropy.png", "prefix_rho.png"})
    EXPECT_TRUE(is_png(out / png)) << png;
  const int R = s["spectrum"]["resolution"];
  EXPECT_EQ(fs::file_size(out / "periodogram.f32"), std::size_t(R) * R * 4);
  // Nothing staged is left behind.
  for (const auto& e : fs::directory_iterator(out)) EXPECT_NE(e.path().filename().string()[0], '.');
}

TEST(AnalyzeCli, SeveralFilesAreRealizations) {
  fs::path dir = scratch_dir("several");
  std::string args = "analyze --no-plots -q";
  for (int s = 0; s < 3; ++s) {
    fs::path csv = dir / (std::to_string(s) + ".csv");
    write_text(csv, csv_of(random_points(500 + 10 * s, 3, 40 + s)));
    args += " '" + csv.string() + "'";
  }
  test::CliResult r = run_pdrt(args + " --out '" + (dir / "out").string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(dir / "out" / "stats.json");
  nlohmann::json s = nlohmann::json::parse(in);
  EXPECT_EQ(s["realizations"], 3);
  ASSERT_EQ(s["per_file"].size(), 3u);
  EXPECT_EQ(s["per_file"][2]["count"], 520);
  EXPECT_EQ(s["count"], 500);  // top level = first file
  EXPECT_EQ(s["spectrum"]["projection"], nlohmann::json::array({0, 1}));
}

TEST(AnalyzeCli, EmptyFileIsRejected) { expect_rejected("empty", "", "1:"); }

TEST(AnalyzeCli, WrongColumnCountIsRejected) { expect_rejected("columns", "x0,x1\n0.1,0.2\n0.3,0.4,0.5\n", "3:"); }

TEST(AnalyzeCli, NonNumericValueIsRejected) { expect_rejected("text", "x0,x1\n0.1,0.2\n0.3,abc\n", "3:"); }

TEST(AnalyzeCli, NanValueIsRejected) { expect_rejected("nan", "x0,x1\n0.1,0.2\n0.3,0.4\nnan,0.5\n", "4:"); }

TEST(AnalyzeCli, CoordinateOutsideUnitCubeIsRejected) { expect_rejected("outside", "x0,x1\n0.1,1.0\n", "2:"); }

TEST(AnalyzeCli, MismatchedDimsAreRejected) {
  fs::path dir = scratch_dir("dims");
  fs::path a = dir / "a.csv", b = dir / "b.csv";
  write_text(a, "x0,x1\n0.1,0.2\n0.3,0.4\n");
  write_text(b, "x0,x1,x2\n0.1,0.2,0.3\n");
  fs::path out = dir / "out";
  test::CliResult r =
      run_pdrt("analyze '" + a.string() + "' '" + b.string() + "' --no-plots --out '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find(b.string() + ":1:"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(out / "stats.json"));
}

TEST(AnalyzeCli, BadResolutionIsAUsageError) {
  fs::path dir = scratch_dir("resolution");
  fs::path csv = dir / "p.csv";
  write_text(csv, "x0,x1\n0.1,0.2\n0.3,0.4\n");
  test::CliResult r = run_pdrt("analyze '" + csv.string() + "' --resolution 33 --out '" + (dir / "out").string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--resolution"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out" / "stats.json"));
}
