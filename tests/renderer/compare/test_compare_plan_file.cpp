// The files a plan's readers parse (renderer/compare/compare_plan_file.h): a number that is
// not an integer of the field's type is refused by name. Found with tests/fuzz/fuzz_plan.cpp:
// nlohmann's get<int>() converted 1e300 to int (undefined behaviour) and truncated 2.5.
#include "renderer/compare/compare_plan_file.h"
#include "sampling/core/errors.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace pdrt {
namespace {

// A plan of one uniform job whose "spp" is written as `spp`.
std::string plan_with_spp(const std::string& spp) {
  return R"({"pdrt_plan": 1, "id": "0123456789abcdef", "scene_hash": "a1b2c3d4e5f60718", "request": {},
  "jobs": [{"kind": "uniform", "sampler": "poisson", "spp": )" +
         spp + R"(, "seed_index": 0, "half": 0, "sweep_step": 0}]})";
}

// The message read_compare_plan refuses `plan_json` with, or "accepted".
std::string read_error(const std::string& plan_json) {
  const auto dir = std::filesystem::temp_directory_path() / ("pdrt_plan_file_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "plan.json") << plan_json;
  std::string result = "accepted";
  try {
    read_compare_plan(dir);
  } catch (const InputError& e) {
    result = e.what();
  }
  std::filesystem::remove_all(dir);
  return result;
}

const nlohmann::json kMark = nlohmann::json::parse(R"({"plan": "0123456789abcdef", "index": 0, "seconds": 0.1,
  "build_seconds": 0.01, "cpu_seconds": 0.2, "build_cpu_seconds": 0.01, "spp_mean": 4.0, "samples": 1024,
  "adaptive_rounds": 0, "threads": 2, "profile_ticks": 40, "profile_sampler_ticks": 3, "cached": false, "file": ""})");

TEST(ComparePlanFile, ReadsAnIntegerSpp) { EXPECT_EQ(read_error(plan_with_spp("4")), "accepted"); }

TEST(ComparePlanFile, RefusesASppOutsideTheIntegersByName) {
  EXPECT_NE(read_error(plan_with_spp("1e300"))
                .find("plan.json: not a pdrt compare plan (\"spp\" must be an integer in [-2147483648, 2147483647], "
                      "got 1e+300)"),
            std::string::npos);
}

TEST(ComparePlanFile, RefusesAFractionalSppRatherThanTruncatingIt) {
  EXPECT_NE(read_error(plan_with_spp("2.5")).find("\"spp\" must be an integer"), std::string::npos);
}

TEST(ComparePlanFile, RefusesAMarkWhoseSampleCountIsNotAnInteger) {
  nlohmann::json mark = kMark;
  mark["samples"] = 1e300;
  try {
    job_mark_render(mark);
    FAIL() << "accepted samples 1e300";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("\"samples\" must be an integer"), std::string::npos) << e.what();
  }
}

TEST(ComparePlanFile, AMarkWhoseIndexIsNotAnIntegerIsNotTheJobs) {
  ComparePlan plan;
  plan.id = "0123456789abcdef";
  nlohmann::json mark = kMark;
  ASSERT_TRUE(mark_is_for(mark, plan, 0));
  mark["index"] = 0.5;  // was truncated to job 0
  EXPECT_FALSE(mark_is_for(mark, plan, 0));
}

}  // namespace
}  // namespace pdrt
