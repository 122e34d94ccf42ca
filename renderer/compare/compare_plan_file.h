#pragma once
// The files a plan's readers parse (compare_plan.h): DIR/plan.json (the request, the scene's
// hash and the jobs) and a finished job's mark DIR/jobs/NNNN.json (its timings and counts).
// Parsing only, apart from the rendering and writing in compare_plan.cpp, so that it can be
// tested and fuzzed alone (tests/fuzz/fuzz_plan.cpp).
#include "renderer/compare/compare_job.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace pdrt {

inline constexpr int kComparePlanVersion = 1;  // "pdrt_plan" in plan.json

struct ComparePlan {
  std::filesystem::path dir;
  nlohmann::json request;   // what recreates the scene and the options (the command line's)
  uint64_t scene_hash = 0;  // of CompareOptions::scene_content when planned
  std::string id;           // of the request, the scene and the jobs: a job's result names its plan
  std::vector<CompareJob> jobs;
};

// Reads DIR/plan.json (InputError naming the file when it is missing or not a plan).
ComparePlan read_compare_plan(const std::filesystem::path& dir);

// One job of plan.json's "jobs" (std::exception when malformed).
CompareJob job_from_json(const nlohmann::json& v);

// Whether a job's mark names this plan and job `index`; false for a malformed one.
bool mark_is_for(const nlohmann::json& mark, const ComparePlan& plan, int index);

// A finished job's timings and counts from its mark, the image left empty (std::exception
// when a field is missing or of the wrong type).
CompareRender job_mark_render(const nlohmann::json& mark);

}  // namespace pdrt
