#pragma once
// What `pdrt compare` was asked on its command line, and how that becomes a scene and
// CompareOptions. A plan stores the request (as JSON), so `pdrt run-job` and `pdrt collect`
// rebuild exactly the scene and options the in-process comparison would use.
#include "renderer/compare/compare.h"
#include "renderer/compare/compare_plan.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace pdrt::cli {

// "random,jitter,poisson,poisson-065,sobol": kCompareDefaultSamplers. Inline (the name table
// only), so the plan readers link without the samplers (tests/fuzz).
inline std::string default_samplers() {
  std::string s;
  for (const std::string& name : compare_default_sampler_names()) s += (s.empty() ? "" : ",") + name;
  return s;
}

struct CompareRequest {
  std::string scene, label;  // the file to load; the name the report shows (default: scene)
  bool strict = false;
  std::string samplers = default_samplers(), spp = "1,4,16,64,256", cache;
  std::optional<int> width, height;
  int reference_spp = 4096, threads = 0, seeds = 4;
  double adaptive_threshold = 0;
  int adaptive_target_spp = 64;
  std::string adaptive_metric, adaptive_variance, adaptive_decision, reconstruction;
  std::string demo_crop;  // "x,y,size": the demonstration sheet's square (default: the detail window)
  bool adaptive = false, quiet = false, allow_long = false;
  bool regularize = false;  // biased path regularisation for the renders (never the reference); off unless asked
};

nlohmann::json request_json(const CompareRequest& r);
CompareRequest request_from_json(const nlohmann::json& j);  // std::exception on a malformed one

// The request a plan was written for (InputError naming DIR/plan.json when it is malformed).
CompareRequest plan_request(const ComparePlan& plan);

// The options alone, validated (UsageError); out unset.
CompareOptions compare_options(const CompareRequest& r);

struct PreparedCompare {
  SceneDesc scene;
  CompareOptions options;  // out unset
};

// Validates the options (UsageError), loads the scene (InputError) and applies the overrides;
// checks the film's memory and the sample budget when `check_budget`.
PreparedCompare prepare_compare(const CompareRequest& r, bool check_budget);

// Runs plot_compare.py on a report directory (throws naming the log when it fails).
void write_compare_plots(const std::string& python, const std::filesystem::path& out);

}  // namespace pdrt::cli
