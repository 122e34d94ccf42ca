#pragma once
// `pdrt compare`: renders a scene with several samplers at several sample counts, measures
// each image's error against an independent high-spp reference, and writes a report
// (results.json/csv, images, heat maps, crops, plots, index.html).
#include "renderer/scene/scene_desc.h"
#include "sampling/samplers/sampler.h"

#include <array>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace pdrt {

struct CompareOptions {
  std::vector<std::string> samplers = compare_default_sampler_names();  // sampling/samplers/sampler_names.h
  std::vector<int> spp{1, 4, 16, 64, 256};
  bool adaptive = false;
  // > 0: the centre of the threshold sweep (else the scene's, else the metric's default). The
  // sweep's metric, variance and decision are the scene's (with the command line's overrides).
  double adaptive_threshold = 0;
  int adaptive_target_spp = 64;  // the uniform spp whose RMSE the threshold sweep must reach
  int seeds = 4;                 // independent renders per (sampler, spp): compare_seed(scene seed, 0..seeds-1)
  int reference_spp = 4096;      // rendered as two independent halves, whose difference measures its noise
  // The demonstration sheet's square {x, y, side} in the image; unset: the detail window.
  std::optional<std::array<int, 3>> demo_crop;
  std::string reference_sampler = sampler_name(SamplerKind::Sobol);
  int threads = 0;
  bool quiet = false;
  std::filesystem::path out;
  std::filesystem::path cache_dir;  // reference cache; empty = cache_dir() / "references"
  std::string scene_label;          // for the report
  std::string scene_content;        // the scene file's bytes, part of the reference cache key
};

// Validates options (UsageError) before any rendering.
void validate_compare_options(const CompareOptions& o);

// The most camera samples the comparison may take: the reference, every sampler at every
// --spp with every seed and, with --adaptive, at most 13 sweep runs per sampler of at most the largest --spp.
double compare_sample_count(const CompareOptions& o, int width, int height);

struct CompareJob;
struct CompareRender;
// Where the report gets a job's render: rendered now, or read from a plan's finished job.
using CompareJobSource = std::function<CompareRender(const CompareJob&)>;

// Writes the report (everything except the plots) into o.out from the jobs' renders, asked for
// in compare_jobs() order (adaptive steps past kSweepAlwaysLastStep only while needed);
// returns the path of results.json.
std::filesystem::path write_compare_report(const SceneDesc& scene, const CompareOptions& o,
                                           const CompareJobSource& source);

// Renders every job in this process and writes the report; returns the path of results.json.
std::filesystem::path run_compare(const SceneDesc& scene, const CompareOptions& o);

}  // namespace pdrt
