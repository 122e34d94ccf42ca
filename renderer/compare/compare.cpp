#include "renderer/compare/compare.h"

#include "renderer/compare/adaptive_sweep.h"
#include "renderer/compare/compare_job.h"
#include "renderer/compare/blurred_heat_maps.h"
#include "renderer/compare/compare_reference.h"
#include "renderer/compare/convergence_view.h"
#include "renderer/compare/demonstration_sheet.h"
#include "renderer/compare/detail_crops.h"
#include "renderer/compare/heat_maps.h"
#include "renderer/compare/report_context.h"
#include "renderer/compare/results_csv.h"
#include "renderer/compare/results_json.h"
#include "renderer/compare/screen_maps.h"
#include "renderer/compare/uniform_runs.h"
#include "renderer/render/adaptive_metric.h"
#include "sampling/core/atomic_file.h"
#include "sampling/core/errors.h"
#include "sampling/core/output_directory.h"
#include "sampling/samplers/sampler.h"

#include <algorithm>
#include <set>

namespace pdrt {

namespace fs = std::filesystem;

namespace {

// The report's directory with images/, errors/ and spectra/, and results.json writable.
void create_report_directories(const CompareOptions& o) {
  create_output_directory(o.out);
  std::error_code ec;
  for (const char* sub : {"images", "errors", "spectra"}) {
    fs::create_directories(o.out / sub, ec);
    if (ec) throw InputError((o.out / sub).string() + ": cannot create directory (" + ec.message() + ")");
  }
  check_writable(o.out / "results.json");
}

}  // namespace

void validate_compare_options(const CompareOptions& o) {
  if (o.samplers.empty()) throw UsageError("--samplers: give at least one sampler");
  std::set<std::string> seen;
  for (const auto& s : o.samplers) {
    SamplerKind kind{};
    if (!parse_sampler(s, &kind))
      throw UsageError("--samplers: unknown sampler \"" + s + "\" (" + sampler_name_list() + ")");
    if (!seen.insert(s).second) throw UsageError("--samplers: \"" + s + "\" given twice");
  }
  if (o.spp.empty()) throw UsageError("--spp: give at least one sample count");
  for (std::size_t i = 0; i < o.spp.size(); ++i) {
    if (o.spp[i] < 1) throw UsageError("--spp: sample counts must be >= 1, got " + std::to_string(o.spp[i]));
    if (i && o.spp[i] <= o.spp[i - 1]) throw UsageError("--spp: sample counts must increase");
  }
  if (o.adaptive_threshold < 0) throw UsageError("--adaptive-threshold must be > 0");
  if (o.adaptive && std::find(o.spp.begin(), o.spp.end(), o.adaptive_target_spp) == o.spp.end())
    throw UsageError("--adaptive-target-spp " + std::to_string(o.adaptive_target_spp) +
                     " must be one of the --spp sample counts");
  if (o.seeds < 1) throw UsageError("--seeds must be >= 1, got " + std::to_string(o.seeds));
  if (o.reference_spp < 1) throw UsageError("--reference-spp must be >= 1, got " + std::to_string(o.reference_spp));
  if (o.reference_spp < 4 * o.spp.back())
    throw UsageError("--reference-spp must be at least 4x the largest --spp (" + std::to_string(o.spp.back()) +
                     "), i.e. >= " + std::to_string(4 * o.spp.back()) + ", got " + std::to_string(o.reference_spp));
}

double compare_sample_count(const CompareOptions& o, int width, int height) {
  double per_pixel = o.reference_spp;
  for (int spp : o.spp) per_pixel += double(o.seeds) * double(o.samplers.size()) * spp;
  if (o.adaptive && !o.spp.empty())
    per_pixel += double(kSweepLastStep - kSweepFirstStep + 1) * double(o.samplers.size()) * o.spp.back();
  return per_pixel * width * height;
}

// The stages in order, each adding to the results what the later ones read: the reference,
// the uniform runs, their heat maps, blurred-error maps, FLIP maps, spectrum images, crops and demonstration sheet,
// the convergence view, the adaptive sweep; then the files written from the results alone.
fs::path write_compare_report(const SceneDesc& base, const CompareOptions& o, const CompareJobSource& source) {
  validate_compare_options(o);
  const ReportContext ctx = report_context(base, o, source);
  validate_demo_crop(o, ctx.width, ctx.height);
  create_report_directories(o);
  CompareResults results;
  results.reference = render_reference(ctx);
  render_uniform_runs(ctx, results);
  write_heat_maps(ctx, results);
  write_blurred_heat_maps(ctx, results);
  write_screen_maps(ctx, results);
  write_detail_crops(ctx, results);
  write_demonstration_sheet(ctx, results);
  results.convergence = convergence_view(o, results.runs);
  if (o.adaptive) {
    run_adaptive_sweep(ctx, results);
    write_adaptive_csv(ctx, results);
  }
  write_results_csv(ctx, results);
  return write_results_json(ctx, results);
}

fs::path run_compare(const SceneDesc& base, const CompareOptions& o) {
  return write_compare_report(base, o, [&](const CompareJob& job) { return render_job(base, o, job); });
}

}  // namespace pdrt
