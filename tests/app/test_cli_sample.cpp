// `pdrt sample`: the command contract and its answers to bad input.
#include "tests/support/cli_runner.h"
#include "sampling/core/point_csv.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace pdrt {
namespace {

using test::run_pdrt;

class SampleCli : public ::testing::Test {
 protected:
  void SetUp() override { dir = test::scratch_dir("sample"); }
  void TearDown() override { std::filesystem::remove_all(dir); }
  std::string out() const { return (dir / "points.csv").string(); }
  // Bad input: the given exit code, one line on stderr naming `what`, and no output file.
  void expect_refused(const std::string& args, int code, const std::string& what) {
    auto r = run_pdrt("sample " + args + " -o " + out());
    EXPECT_EQ(r.exit_code, code) << args << "\n" << r.err;
    EXPECT_EQ(test::line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << "message should name " << what << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(out())) << args;
  }
  std::filesystem::path dir;
};

TEST_F(SampleCli, WritesHeaderAndPointsInGenerationOrder) {
  auto r = run_pdrt("sample --method mccool --dim 3 --count 50 --seed 4 -q -o " + out());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(out());
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "x0,x1,x2,radius");
  PointSet ps = read_point_csv(out());
  EXPECT_EQ(ps.size(), 50u);
  EXPECT_EQ(ps.dim, 3);
  EXPECT_TRUE(std::is_sorted(ps.radius.rbegin(), ps.radius.rend()));
}

TEST_F(SampleCli, MethodsWithoutRadiusWriteOnlyCoordinates) {
  ASSERT_EQ(run_pdrt("sample -m jitter -n 16 -q -o " + out()).exit_code, 0);
  std::ifstream in(out());
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "x0,x1");
}

TEST_F(SampleCli, RejectsDimensionZero) { expect_refused("-m random -d 0 -n 10", 2, "--dim"); }
TEST_F(SampleCli, RejectsDimensionAboveMaximum) { expect_refused("-m gamito -d 6 -n 10", 2, "--dim"); }
TEST_F(SampleCli, RejectsNonPositiveCount) { expect_refused("-m random -n 0", 2, "--count"); }
TEST_F(SampleCli, RejectsNegativeCount) { expect_refused("-m random -n -5", 2, "--count"); }
TEST_F(SampleCli, RejectsCountTooLargeForMemory) { expect_refused("-m random -d 2 -n 900000000000", 2, "GiB"); }
TEST_F(SampleCli, RejectsRadiusTooSmallForMemory) { expect_refused("-m gamito -d 2 -r 1e-9", 2, "GiB"); }
TEST_F(SampleCli, RejectsZeroRadius) { expect_refused("-m bridson -r 0", 2, "--radius"); }
TEST_F(SampleCli, RejectsNaNRadius) { expect_refused("-m bridson -r nan", 2, "--radius"); }
TEST_F(SampleCli, RejectsRadiusTooLargeForTwoPoints) { expect_refused("-m dart -d 2 -r 2", 2, "--radius"); }
TEST_F(SampleCli, RejectsUnknownMethod) { expect_refused("-m sobolev -n 10", 2, "sobolev"); }
TEST_F(SampleCli, RejectsCountWithRadius) { expect_refused("-m gamito -n 10 -r 0.1", 2, "--radius"); }
TEST_F(SampleCli, RejectsRadiusForCountOnlyMethod) { expect_refused("-m mccool -r 0.1", 2, "--radius"); }

TEST_F(SampleCli, RejectsUnwritableOutputBeforeGenerating) {
  std::ofstream(dir / "a-file") << "not a directory";
  auto r = run_pdrt("sample -m random -n 10 -o " + (dir / "a-file" / "sub" / "p.csv").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(test::line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("a-file"), std::string::npos) << r.err;
}

TEST_F(SampleCli, CreatesMissingOutputDirectories) {
  const auto out = dir / "out" / "nested" / "p.csv";
  auto r = run_pdrt("sample -m random -n 10 -q -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_point_csv(out).size(), 10u);
}

}  // namespace
}  // namespace pdrt
