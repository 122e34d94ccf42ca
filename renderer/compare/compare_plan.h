#pragma once
// A comparison as a plan of independent jobs (compare_job.h), for running on many machines:
// DIR/plan.json lists the jobs and the request that recreates the scene and the options;
// a job writes its render into DIR/jobs/ (images first, then NNNN.json, the mark that it
// finished); the report is written from the finished jobs exactly as `pdrt compare` writes it.
// DIR/jobs.txt lists the job indices, most expensive first, for `xargs -P` / GNU parallel;
// DIR/slurm/ holds a job-array script, the collect script and their submitter.
#include "renderer/compare/compare_job.h"
#include "renderer/compare/compare_plan_file.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace pdrt {

// Writes the plan into `dir` (created). Planning again with the same request and scene keeps
// the finished jobs; a different plan makes them stale (they are redone). `pdrt` is the
// executable the generated scripts run.
ComparePlan write_compare_plan(const std::filesystem::path& dir, const nlohmann::json& request, const CompareOptions& o,
                               const std::filesystem::path& pdrt);

// InputError when the scene's content no longer matches the plan's.
void check_plan_scene(const ComparePlan& plan, const CompareOptions& o);

// A job is finished when its NNNN.json names this plan and its images are there.
bool job_finished(const ComparePlan& plan, int index);
std::vector<int> unfinished_jobs(const ComparePlan& plan);

// Renders job `index` and writes its result (atomically: a killed job leaves no mark and is
// redone from scratch); does nothing when it has already finished.
void run_plan_job(const ComparePlan& plan, int index, const SceneDesc& base, const CompareOptions& o);

// The finished result of `job` (InputError when it is not finished).
CompareRender read_plan_job(const ComparePlan& plan, const CompareJob& job);

// The jobs rank `rank` of `size` runs: longest first, each to the least loaded rank (LPT),
// a fixed assignment that balances the estimated cost without a queue.
std::vector<int> jobs_for_rank(const ComparePlan& plan, const CompareOptions& o, int rank, int size);

}  // namespace pdrt
