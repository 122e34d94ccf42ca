#pragma once
// The renders a comparison is made of, as independent jobs: the reference's two halves, every
// (sampler, spp, seed) and every adaptive sweep step. `pdrt compare` runs them in process;
// a plan (compare_plan.h) runs them anywhere and collects them. Either way the report is
// computed from the same CompareRender values, so its numbers are the same.
#include "renderer/compare/compare.h"
#include "renderer/render/film.h"
#include "sampling/samplers/sampler_profile.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace pdrt {

struct CompareJob {
  enum class Kind { Reference, Uniform, Adaptive };
  Kind kind = Kind::Uniform;
  std::string sampler;  // Uniform, Adaptive
  int spp = 0;          // Uniform
  int seed_index = 0;   // Uniform: compare_seed(scene seed, seed_index)
  int half = 0;         // Reference: 0 or 1
  int sweep_step = 0;   // Adaptive: threshold = centre x 2^sweep_step
};

// Adaptive sweep steps: -4..4 always, and up to 8 while even the cheapest run still reaches the
// target error. A plan holds every step; the report reads only those the rule asks for.
inline constexpr int kSweepFirstStep = -4, kSweepLastStep = 8, kSweepAlwaysLastStep = 4;

// What the report needs of one render.
struct CompareRender {
  Image image;  // rgb; and samples for adaptive jobs
  double seconds = 0, build_seconds = 0, cpu_seconds = 0, build_cpu_seconds = 0, spp_mean = 0;
  int64_t samples = 0;
  int adaptive_rounds = 0, threads = 0;
  SamplerProfile profile;
  bool cached = false;  // a reference half read from the cache rather than rendered
  std::string file;     // a reference half: where its image is kept
};

// The reference: another sampler and seeds than any test image, rendered as two independent
// halves (their difference measures its noise) and cached by content.
struct ReferenceSetup {
  SceneDesc scene;  // spp and seed of the whole reference
  std::array<int, 2> half_spp{};
  std::array<uint64_t, 2> half_seed{};
  std::string key;  // the cache key: scene content, size, sampler, spp, seed, reconstruction, version
  std::array<std::filesystem::path, 2> cache;
};
ReferenceSetup reference_setup(const SceneDesc& base, const CompareOptions& o);

// Every job of a comparison, in the order the report uses them.
std::vector<CompareJob> compare_jobs(const CompareOptions& o);

// Samples per pixel the job may trace (the adaptive maximum for sweep steps): its cost estimate.
double job_cost(const CompareJob& job, const CompareOptions& o);

// "reference half 1/2", "poisson 16 spp seed 2", "poisson adaptive step -4".
std::string describe(const CompareJob& job);

// The adaptive settings of every sweep step (the scene's metric, variance and decision, which
// are the defaults unless the scene or the command line set them, with the sweep's spp range),
// and the sweep's centre threshold.
AdaptiveDesc sweep_adaptive(const SceneDesc& base, const CompareOptions& o);
double sweep_centre(const SceneDesc& base, const CompareOptions& o);
double sweep_threshold(const SceneDesc& base, const CompareOptions& o, int step);

// The scene a job renders: base with the job's sampler, spp, seed and adaptive settings.
SceneDesc job_scene(const SceneDesc& base, const CompareOptions& o, const CompareJob& job);

// Renders a job. A reference half comes from the cache when it holds it, and goes there when
// rendered. Progress on stderr unless o.quiet.
CompareRender render_job(const SceneDesc& base, const CompareOptions& o, const CompareJob& job);

}  // namespace pdrt
