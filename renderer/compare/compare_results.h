#pragma once
// What the stages of `pdrt compare`'s report compute (compare_report.h), in the order they
// run: the reference, the uniform runs, the heat maps and crops, the convergence view and the
// adaptive sweep. results.json and results.csv are written from this value alone.
#include "renderer/compare/compare_job.h"
#include "renderer/compare/convergence.h"
#include "renderer/compare/screen_measures.h"
#include "renderer/compare/seed_statistics.h"
#include "renderer/render/film.h"
#include "sampling/analysis/radial_spectrum.h"
#include "sampling/analysis/stream_analysis.h"
#include "sampling/samplers/sampler_profile.h"

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace pdrt {

// The reference: two independent halves whose difference measures its noise.
struct CompareReference {
  ReferenceSetup setup;
  Image image;                      // the halves' samples-weighted mean
  std::array<Image, 2> halves;      // the halves themselves
  std::array<std::string, 2> file;  // where each half's image is kept
  bool cached = true;               // both halves came from the cache
  double seconds = 0;               // rendering the halves that were not cached
  ReferenceNoise noise;
  // RMSE against the reference with its variance taken out (E[(x - r)^2] = E[(x - I)^2] + Var r).
  double corrected_rmse(const Image& im) const;
};

// One seed's render of a (sampler, spp).
struct SeedRun {
  uint64_t seed = 0;
  double seconds = 0, render_seconds = 0, cpu_seconds = 0, relmse = 0;
  int64_t samples = 0;
  SamplerProfile profile;  // the sampler's share of the passes' CPU ticks
};

// A (sampler, spp) over every seed; `rmse` is the mean over seeds of the reference-corrected RMSE.
struct UniformRun {
  std::string sampler;
  int spp = 0;
  double seconds = 0, render_seconds = 0, cpu_seconds = 0, rmse = 0, relmse = 0, spp_mean = 0;  // means over seeds
  int64_t samples = 0;  // traced by one render (every seed traces the same count)
  SeedStatistics stats;
  std::vector<SeedRun> seeds;
  RadialSpectrum spectrum;           // of the error image, averaged over the seeds (radial_spectrum of screen.spectrum)
  ScreenMeasures screen;             // blurred RMSE, low-frequency share, FLIP, the 2-D error spectrum
  SamplerProfile profile;            // summed over the seeds
  std::vector<StreamAnalysis> used;  // seed 0's samples, per family
  Image image;                       // seed 0's
  std::string image_file, error_file;
  std::string flip_ldr_file, flip_hdr_file, spectrum_file;  // seed 0's FLIP maps, the mean 2-D spectrum
  std::vector<float> blurred_error;  // seed 0's |luminance of the error blurred by kBlurredMapSigma| per pixel
  std::string blurred_error_file;    // its heat map
};

// Side-by-side crops of the reference's most detailed square, one sheet per spp.
struct DetailCrops {
  std::array<int, 3> window{};  // x, y, side
  int zoom = 1;
  std::vector<std::pair<int, std::string>> files;  // (spp, file)
};

// The demonstration sheet (demonstration_sheet.h): samplers x spp of seed-0 crops and their
// blurred-error heat maps, for at most kDemoMaxSamplers x kDemoMaxSpp.
struct DemonstrationSheet {
  bool drawn = false;
  std::string file;
  std::array<int, 3> window{};  // x, y, side: the detail window or --demo-crop
  bool window_given = false;    // from --demo-crop
  int zoom = 1, width = 0, height = 0;
  float scale = 0;        // the heat ramp's top, shared by every cell
  bool labelled = false;  // false when no font was found for the labels
};

// RMSE ~ spp^slope per sampler, and the equal-time view: every sampler's RMSE interpolated at
// common CPU times, with and without the sampler's own share.
struct ConvergenceView {
  std::map<std::string, double> slopes;
  std::map<std::string, SamplerProfile> sampler_cost;  // each sampler's profile summed over its runs
  std::vector<double> seconds;                         // the common times
  std::map<std::string, std::vector<double>> rmse, rmse_without_sampler;
};

// One render of the adaptive threshold sweep.
struct SweepStep {
  int step = 0;  // threshold = centre x 2^step
  double threshold = 0;
  CompareRender render;     // its image only for step 0
  double rmse = 0;          // reference-corrected
  double uniform_rmse = 0;  // uniform sampling's at equal samples (NaN outside the uniform runs' range)
};

// A sampler's threshold sweep, and the samples it needs to reach the uniform RMSE at the
// target spp.
struct SamplerSweep {
  std::string sampler;
  std::vector<SweepStep> steps;
  std::string image, sample_map;  // step 0's image and sample-count map
  std::size_t uniform_run = 0;    // results.runs' index of the uniform run at the target spp
  CostToReach cost{};
  double ratio = 0;  // cost / the uniform run's samples
};

struct AdaptiveSweep {
  AdaptiveDesc settings;               // every step's, but the threshold
  std::vector<SamplerSweep> samplers;  // in --samplers order
};

struct CompareResults {
  int width = 0, height = 0;  // the crop window's (the whole film without one)
  CompareReference reference;
  std::vector<UniformRun> runs;                         // by sampler, then spp
  int threads = 0;                                      // worker threads of the last uniform render
  std::map<int, float> heat_scale;                      // per spp: the error maps' common scale
  std::map<int, float> blurred_heat_scale;              // per spp: the blurred-error maps' common scale
  FlipExposures flip_exposures;                         // HDR-FLIP's, from the reference
  std::map<int, std::array<double, 2>> spectrum_scale;  // per spp: the 2-D spectrum images' log10 power range
  DetailCrops crops;
  DemonstrationSheet demonstration;
  ConvergenceView convergence;
  AdaptiveSweep adaptive;  // with --adaptive
};

}  // namespace pdrt
