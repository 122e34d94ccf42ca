// `pdrt compare --plan DIR`, `pdrt run-job DIR INDEX`, `pdrt collect DIR` (issue 19): a sweep as
// independent jobs whose collected report equals the in-process `compare`, number for number;
// finished jobs are not redone, killed ones are; the Slurm scripts run under a stand-in sbatch.
#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <fstream>
#include <iterator>
#include <set>

namespace fs = std::filesystem;
using namespace pdrt::test;
using nlohmann::json;

namespace {

const std::string kPdrt = std::string("'") + PDRT_BINARY + "'";

fs::path write_scene(const fs::path& dir, const std::string& albedo = "0.8") {
  fs::path p = dir / "scene.json";
  std::ofstream(p) << R"({
  "camera": {"position": [0, 0, 4], "look_at": [0, 0, 0]},
  "film": {"width": 16, "height": 12},
  "sampler": {"spp": 4},
  "materials": {"grey": {"type": "glossy", "albedo": [)"
                   << albedo << ", " << albedo << ", " << albedo << R"(], "roughness": 0.4}},
  "objects": [{"type": "sphere", "material": "grey", "radius": 1}],
  "lights": [{"type": "environment", "radiance": [1, 1, 1]}]
}
)";
  return p;
}

const std::string kSweep =
    " --samplers jitter,poisson --spp 2,8 --seeds 2 --reference-spp 64 --adaptive --adaptive-target-spp 8";

// Plans `sweep` for d/scene.json into d/plan (reference cache d/c).
CliResult write_plan(const fs::path& d, const std::string& sweep) {
  return run_pdrt("compare " + (d / "scene.json").string() + " --plan " + (d / "plan").string() + sweep +
                  " --cache-dir " + (d / "c").string());
}

int shell(const std::string& cmd) {
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Keys whose values are clocks, thread counts or where files were kept: they differ between
// any two runs. Everything else must be equal.
const std::set<std::string> kRunDependent = {
    "seconds",    "render_seconds", "cpu_seconds", "sampler_share", "sampler_cpu_seconds",
    "equal_time", "threads",        "cached",      "file"};

void expect_same_numbers(const json& a, const json& b, const std::string& path = "") {
  ASSERT_EQ(a.type(), b.type()) << path;
  if (a.is_object()) {
    ASSERT_EQ(a.size(), b.size()) << path;
    for (auto it = a.begin(); it != a.end(); ++it) {
      ASSERT_TRUE(b.contains(it.key())) << path << "/" << it.key();
      if (!kRunDependent.count(it.key())) expect_same_numbers(it.value(), b[it.key()], path + "/" + it.key());
    }
  } else if (a.is_array()) {
    ASSERT_EQ(a.size(), b.size()) << path;
    for (std::size_t i = 0; i < a.size(); ++i) expect_same_numbers(a[i], b[i], path + "/" + std::to_string(i));
  } else {
    EXPECT_EQ(a, b) << path;
  }
}

// Every PNG of the in-process report exists in the collected one with the same bytes.
void expect_same_images(const fs::path& a, const fs::path& b) {
  int n = 0;
  for (const char* sub : {"images", "errors"})
    for (const auto& e : fs::directory_iterator(a / sub)) {
      ++n;
      EXPECT_EQ(slurp(e.path()), slurp(b / sub / e.path().filename())) << e.path().filename();
    }
  EXPECT_GT(n, 10);
}

}  // namespace

TEST(CliComparePlan, PlanRunThroughXargsAndCollectedEqualsInProcessCompare) {
  const fs::path d = scratch_dir("plan_xargs");
  const fs::path scene = write_scene(d);
  auto r = run_pdrt("compare " + scene.string() + " --out " + (d / "inproc").string() + kSweep + " --cache-dir " +
                    (d / "cache-a").string() + " --no-plots --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Another cache (d/c): the plan renders its own reference rather than reading the first one's.
  r = write_plan(d, kSweep);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json plan = json::parse(std::ifstream(d / "plan" / "plan.json"));
  ASSERT_EQ(plan["jobs"].size(), 2u + 2 * 2 * 2 + 2 * 13) << "reference halves, sampler x spp x seed, sweep steps";
  ASSERT_EQ(shell("xargs -P 2 -n 1 " + kPdrt + " run-job '" + (d / "plan").string() + "' --quiet --threads 1 < '" +
                  (d / "plan" / "jobs.txt").string() + "'"),
            0);
  r = run_pdrt("collect " + (d / "plan").string() + " --no-plots --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json a = json::parse(std::ifstream(d / "inproc" / "results.json"));
  const json b = json::parse(std::ifstream(d / "plan" / "results.json"));
  EXPECT_FALSE(b["reference"]["cached"].get<bool>());
  expect_same_numbers(a, b);
  expect_same_images(d / "inproc", d / "plan");
}

TEST(CliComparePlan, FinishedJobsAreNotRedone) {
  const fs::path d = scratch_dir("plan_idempotent");
  write_scene(d);
  const std::string plan = (d / "plan").string();
  ASSERT_EQ(write_plan(d, kSweep).exit_code, 0);
  auto r = run_pdrt("run-job " + plan + " 3 4");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("job 3 (jitter 2 spp seed 1) done"), std::string::npos) << r.err;
  const auto stamp = fs::last_write_time(d / "plan" / "jobs" / "0003.json");
  r = run_pdrt("run-job " + plan + " 3");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("job 3 (jitter 2 spp seed 1) had already finished"), std::string::npos) << r.err;
  EXPECT_EQ(fs::last_write_time(d / "plan" / "jobs" / "0003.json"), stamp);
  // Planning the same sweep again keeps them; a different sweep makes them stale.
  r = write_plan(d, kSweep);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("36 jobs (34 to run)"), std::string::npos) << r.err;
  r = write_plan(d, kSweep + " --reconstruction splat");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("36 jobs (36 to run)"), std::string::npos) << r.err;
}

TEST(CliComparePlan, KilledJobIsRedoneFromScratch) {
  const fs::path d = scratch_dir("plan_killed");
  write_scene(d);
  const std::string plan = (d / "plan").string();
  // Job 0, the first reference half (131072 spp at 16 x 12), runs for much longer than a second.
  ASSERT_EQ(write_plan(d, " --samplers jitter --spp 2 --seeds 1 --reference-spp 262144").exit_code, 0);
  const int status = shell("timeout -s KILL 1 " + kPdrt + " run-job " + plan + " 0 --quiet --threads 1 2>/dev/null");
  ASSERT_EQ(status, 137) << "killed by timeout";
  EXPECT_FALSE(fs::exists(d / "plan" / "jobs" / "0000.json")) << "no mark: the job did not finish";
  auto r = run_pdrt("collect " + plan + " --no-plots");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("3 of 3 jobs have not finished (0 1 2)"), std::string::npos) << r.err;
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_FALSE(fs::exists(d / "plan" / "results.json"));
  // A mark from a killed job's partial write is not trusted either.
  std::ofstream(d / "plan" / "jobs" / "0002.json") << "{\"plan\": ";
  r = run_pdrt("run-job " + plan + " 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("done in"), std::string::npos) << r.err;
}

TEST(CliComparePlan, BadPlanInputIsRefusedWithOneLine) {
  const fs::path d = scratch_dir("plan_bad");
  const fs::path scene = write_scene(d);
  const std::string plan = (d / "plan").string();
  ASSERT_EQ(write_plan(d, kSweep).exit_code, 0);
  struct Case {
    std::string args;
    int code;
    std::string says;
  };
  for (const Case& c :
       std::vector<Case>{{"run-job " + plan, 2, "give job indices or --all"},
                         {"run-job " + plan + " 0 --all", 2, "give job indices or --all"},
                         {"run-job " + plan + " 36", 2, "job index 36: the plan in " + plan + " has jobs 0..35"},
                         {"run-job " + plan + " -1", 2, "job index -1"},
                         {"run-job " + (d / "nowhere").string() + " 0", 1, "no compare plan here"},
                         {"collect " + (d / "nowhere").string(), 1, "no compare plan here"},
                         {"compare " + scene.string() + " --plan " + plan + " --out " + (d / "o").string(), 2,
                          "--out and --plan: give one"},
                         {"compare " + scene.string(), 2, "give --out DIR (the report) or --plan DIR"},
                         {"compare " + scene.string() + " --plan ''", 2, "--plan: empty path"}}) {
    auto r = run_pdrt(c.args);
    EXPECT_EQ(r.exit_code, c.code) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(line_count(r.err), 1) << c.args << ": " << r.err;
  }
  std::ofstream(d / "plan" / "plan.json") << "{\"pdrt_plan\": 1}";
  auto r = run_pdrt("collect " + plan);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("plan.json: not a pdrt compare plan"), std::string::npos) << r.err;
  // A scene edited after planning: the jobs would not be the planned ones.
  ASSERT_EQ(write_plan(d, kSweep).exit_code, 0);
  write_scene(d, "0.5");
  r = run_pdrt("run-job " + plan + " 0");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("the scene changed since the plan"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(d / "plan" / "jobs" / "0000.json"));
}

// Found with tests/fuzz/fuzz_plan.cpp: a request's integer written as 1e300 in a hand-edited
// plan.json is refused in one line naming the file and the field (its conversion to int was
// undefined behaviour).
TEST(CliComparePlan, RequestIntegerOutOfRangeIsRefusedWithOneLine) {
  const fs::path d = scratch_dir("plan_request_range");
  std::ifstream in(fs::path(PDRT_TEST_DATA_DIR) / "fuzz" / "plan" / "plan.json");
  std::string plan((std::istreambuf_iterator<char>(in)), {});
  const std::size_t at = plan.find("\"width\": null");
  ASSERT_NE(at, std::string::npos);
  plan.replace(at, 13, "\"width\": 1e300");
  std::ofstream(d / "plan.json") << plan;
  auto r = run_pdrt("run-job " + d.string() + " 0");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("plan.json: request: \"width\" must be an integer in [-2147483648, 2147483647], got 1e+300"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(line_count(r.err), 1) << r.err;
}

// The generated Slurm scripts pass `bash -n`; under a stand-in `sbatch` that runs an array's
// tasks one after another, submit.sh runs every job and then the collect step (with plots).
TEST(CliComparePlan, SlurmScriptsRunUnderStandInSbatch) {
  const fs::path d = scratch_dir("plan_slurm");
  write_scene(d);
  const std::string plan = (d / "plan").string();
  ASSERT_EQ(write_plan(d, " --samplers jitter,sobol --spp 2,8 --seeds 2 --reference-spp 64").exit_code, 0);
  for (const char* s : {"run-jobs.sbatch", "collect.sbatch", "submit.sh"})
    EXPECT_EQ(shell("bash -n '" + (d / "plan" / "slurm" / s).string() + "'"), 0) << s;
  const std::string array = slurp(d / "plan" / "slurm" / "run-jobs.sbatch");
  EXPECT_NE(array.find("#SBATCH --array=0-9\n"), std::string::npos) << array;
  fs::create_directories(d / "bin");
  std::ofstream(d / "bin" / "sbatch") << R"(#!/bin/bash
# Stand-in for Slurm's sbatch: runs an array's tasks in turn, or the script once.
script=""; dep=""
for a in "$@"; do case "$a" in --dependency=afterok:*) dep="${a#--dependency=afterok:}" ;; --*) ;; *) script="$a" ;; esac; done
if [ -n "$dep" ] && [ "$dep" != 41 ]; then echo "unknown dependency $dep" >&2; exit 1; fi
range=$(sed -n 's/^#SBATCH --array=//p' "$script")
out=$(sed -n 's/^#SBATCH --output=//p' "$script")
if [ -n "$range" ]; then
  for ((i = ${range%-*}; i <= ${range#*-}; i++)); do
    SLURM_ARRAY_TASK_ID=$i SLURM_CPUS_PER_TASK=1 bash "$script" > "${out//%a/$i}" 2>&1 || exit 1
  done
  echo 41
else
  bash "$script" > "$out" 2>&1 || exit 1
  echo 42
fi
)";
  fs::permissions(d / "bin" / "sbatch", fs::perms::owner_all);
  ASSERT_EQ(shell("PATH='" + (d / "bin").string() + "':\"$PATH\" bash '" +
                  (d / "plan" / "slurm" / "submit.sh").string() + "' >/dev/null 2>&1"),
            0);
  for (int i = 0; i < 10; ++i)
    EXPECT_TRUE(fs::exists(d / "plan" / "slurm" / ("job-" + std::to_string(i) + ".log"))) << i;
  const json results = json::parse(std::ifstream(d / "plan" / "results.json"));
  EXPECT_EQ(results["runs"].size(), 4u);
  EXPECT_TRUE(fs::exists(d / "plan" / "index.html"));
}

// `mpirun -np 2 pdrt run-job DIR --all`: the ranks share the jobs, each runs once, and the plan
// collects. (Open MPI refuses root unless told, and CI runs as root.)
TEST(CliComparePlan, MpirunRanksShareTheJobsOnce) {
  const fs::path d = scratch_dir("plan_mpirun");
  write_scene(d);
  const std::string plan = (d / "plan").string();
  ASSERT_EQ(write_plan(d, " --samplers jitter,poisson --spp 2,8 --seeds 2 --reference-spp 64").exit_code, 0);
  const fs::path err = d / "mpirun.txt";
  ASSERT_EQ(shell("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun --oversubscribe --bind-to none "
                  "--timeout 120 -np 2 " +
                  kPdrt + " run-job " + plan + " --all --threads 1 >/dev/null 2>'" + err.string() + "'"),
            0)
      << slurp(err);
  const std::string log = slurp(err);
  for (int i = 0; i < 10; ++i) {
    const std::string line = "job " + std::to_string(i) + " (";
    const std::size_t at = log.find(line);
    EXPECT_NE(at, std::string::npos) << i << "\n" << log;
    EXPECT_EQ(log.find(line, at + 1), std::string::npos) << "job " << i << " ran twice\n" << log;
  }
  EXPECT_NE(log.find("10 of 10 jobs finished"), std::string::npos) << log;
  auto r = run_pdrt("collect " + plan + " --no-plots --quiet");
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

// A job that fails on one rank ends the whole run, naming the rank and the job, instead of
// leaving the other ranks waiting.
TEST(CliComparePlan, MpirunJobFailureNamesTheRankAndJob) {
  const fs::path d = scratch_dir("plan_mpirun_fail");
  write_scene(d);
  const std::string plan = (d / "plan").string();
  ASSERT_EQ(write_plan(d, " --samplers jitter,poisson --spp 2,8 --seeds 2 --reference-spp 64").exit_code, 0);
  fs::create_directories(d / "plan" / "jobs" / "0007.exr");  // its image cannot be written
  const fs::path err = d / "mpirun.txt";
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_NE(shell("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun --oversubscribe --bind-to none "
                  "--timeout 120 -np 2 " +
                  kPdrt + " run-job " + plan + " --all --threads 1 >/dev/null 2>'" + err.string() + "'"),
            0);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 30);
  const std::string log = slurp(err);
  // Job 7 is rank 1's in the longest-first share (not rank 0's, whose errors main prints anyway).
  EXPECT_NE(log.find("pdrt: rank 1: job 7 (poisson 2 spp seed 1): "), std::string::npos) << log;
}
