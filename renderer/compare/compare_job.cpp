#include "renderer/compare/compare_job.h"

#include "renderer/compare/seed_statistics.h"
#include "renderer/render/adaptive_metric.h"
#include "renderer/image/image_output.h"
#include "renderer/render/renderer.h"
#include "renderer/scene/crop_window.h"
#include "sampling/core/cache_dir.h"
#include "sampling/core/derived_seeds.h"
#include "sampling/core/errors.h"
#include "sampling/core/hash.h"
#include "sampling/core/rng.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pdrt {

namespace fs = std::filesystem;

namespace {

// The reference cache's key hash started from 1469598103934665603, the FNV basis short of its
// last digit; kept, so references cached by earlier versions are still found.
constexpr uint64_t kReferenceKeyBasis = 1469598103934665603ull;

void say(const CompareOptions& o, const std::string& s) {
  if (!o.quiet) std::fprintf(stderr, "pdrt compare: %s\n", s.c_str());
}

CompareRender from_result(RenderResult&& r) {
  CompareRender c;
  c.image = std::move(r.image);
  const RenderStats& s = r.stats;
  c.seconds = s.seconds, c.build_seconds = s.build_seconds, c.cpu_seconds = s.cpu_seconds;
  c.build_cpu_seconds = s.build_cpu_seconds, c.spp_mean = s.spp_mean, c.samples = s.samples;
  c.adaptive_rounds = s.adaptive_rounds, c.threads = s.threads, c.profile = s.sampler_profile;
  return c;
}

// The adaptive sweep's spp range: from the smallest --spp (at least 2) to the largest.
int sweep_min_spp(const CompareOptions& o) { return std::max(2, o.spp.front()); }
int sweep_max_spp(const CompareOptions& o) { return std::max(sweep_min_spp(o), o.spp.back()); }

}  // namespace

ReferenceSetup reference_setup(const SceneDesc& base, const CompareOptions& o) {
  ReferenceSetup r;
  SceneDesc& rs = r.scene;
  rs = base;
  rs.sampler.type = o.reference_sampler;
  rs.sampler.seed = reference_seed(base.sampler.seed);
  rs.sampler.spp = o.reference_spp;
  rs.sampler.adaptive.enabled = false;
  rs.integrator.regularize = false;  // the reference is unbiased, so a regularized run shows its bias
  r.half_spp = {(o.reference_spp + 1) / 2, o.reference_spp / 2};
  r.half_seed = {rs.sampler.seed, reference_half_seed(rs.sampler.seed)};
  const PixelRect crop = crop_pixels(base.film.crop_window, base.film.width, base.film.height);
  const int W = crop.width(), H = crop.height();
  std::string key_text = o.scene_content + "|" + std::to_string(W) + "x" + std::to_string(H) + "|" + rs.sampler.type +
                         "|" + std::to_string(rs.sampler.spp) + "|" + std::to_string(rs.sampler.seed) + "|" +
                         reconstruction_name(rs.film.filter.reconstruction) + "|" + PDRT_VERSION +
                         "|samplers-v4|halves";  // bump when sampler output changes
  if (W != base.film.width || H != base.film.height)
    key_text += "|crop " + std::to_string(crop.x0) + "," + std::to_string(crop.y0) + " of " +
                std::to_string(base.film.width) + "x" + std::to_string(base.film.height);
  char key[32];
  std::snprintf(key, sizeof key, "%016llx", (unsigned long long)fnv1a(key_text, kReferenceKeyBasis));
  r.key = key;
  const fs::path root = o.cache_dir.empty() ? cache_dir() / "references" : o.cache_dir;
  for (int h = 0; h < 2; ++h) r.cache[h] = root / (std::string("ref-") + key + (h ? "-b" : "-a") + ".exr");
  return r;
}

std::vector<CompareJob> compare_jobs(const CompareOptions& o) {
  std::vector<CompareJob> jobs;
  for (int h = 0; h < 2; ++h) {
    CompareJob j;
    j.kind = CompareJob::Kind::Reference, j.half = h;
    jobs.push_back(j);
  }
  for (const auto& name : o.samplers)
    for (int n : o.spp)
      for (int k = 0; k < o.seeds; ++k) {
        CompareJob j;
        j.kind = CompareJob::Kind::Uniform, j.sampler = name, j.spp = n, j.seed_index = k;
        jobs.push_back(j);
      }
  if (o.adaptive)
    for (const auto& name : o.samplers)
      for (int step = kSweepFirstStep; step <= kSweepLastStep; ++step) {
        CompareJob j;
        j.kind = CompareJob::Kind::Adaptive, j.sampler = name, j.sweep_step = step;
        jobs.push_back(j);
      }
  return jobs;
}

double job_cost(const CompareJob& job, const CompareOptions& o) {
  switch (job.kind) {
    case CompareJob::Kind::Reference:
      return job.half == 0 ? (o.reference_spp + 1) / 2 : o.reference_spp / 2;
    case CompareJob::Kind::Uniform:
      return job.spp;
    case CompareJob::Kind::Adaptive:
      return sweep_max_spp(o);
  }
  return 0;
}

std::string describe(const CompareJob& job) {
  switch (job.kind) {
    case CompareJob::Kind::Reference:
      return "reference half " + std::to_string(job.half + 1) + "/2";
    case CompareJob::Kind::Uniform:
      return job.sampler + " " + std::to_string(job.spp) + " spp seed " + std::to_string(job.seed_index);
    case CompareJob::Kind::Adaptive:
      return job.sampler + " adaptive step " + std::to_string(job.sweep_step);
  }
  return "";
}

AdaptiveDesc sweep_adaptive(const SceneDesc& base, const CompareOptions& o) {
  AdaptiveDesc ad = base.sampler.adaptive;  // as a loader left it (defaults when off), with the overrides
  ad.enabled = true;
  ad.min_spp = sweep_min_spp(o);
  ad.max_spp = sweep_max_spp(o);
  return ad;
}

double sweep_centre(const SceneDesc& base, const CompareOptions& o) {
  return o.adaptive_threshold > 0 ? o.adaptive_threshold : effective_threshold(sweep_adaptive(base, o));
}

double sweep_threshold(const SceneDesc& base, const CompareOptions& o, int step) {
  return std::ldexp(sweep_centre(base, o), step);
}

SceneDesc job_scene(const SceneDesc& base, const CompareOptions& o, const CompareJob& job) {
  SceneDesc s = base;
  switch (job.kind) {
    case CompareJob::Kind::Reference: {
      const ReferenceSetup ref = reference_setup(base, o);
      s = ref.scene;
      s.sampler.spp = ref.half_spp[job.half], s.sampler.seed = ref.half_seed[job.half];
      break;
    }
    case CompareJob::Kind::Uniform:
      s.sampler.type = job.sampler;
      s.sampler.spp = job.spp;
      s.sampler.seed = compare_seed(base.sampler.seed, job.seed_index);
      s.sampler.adaptive.enabled = false;
      break;
    case CompareJob::Kind::Adaptive:
      s.sampler.type = job.sampler;
      s.sampler.adaptive = sweep_adaptive(base, o);
      s.sampler.adaptive.threshold = float(sweep_threshold(base, o, job.sweep_step));
      break;
  }
  return s;
}

CompareRender render_job(const SceneDesc& base, const CompareOptions& o, const CompareJob& job) {
  const SceneDesc s = job_scene(base, o, job);
  auto render_scene = [&] {
    auto sampler = make_scene_sampler(s.sampler, s.film);
    RenderOptions ro;
    ro.threads = o.threads;
    ro.quiet = true;
    return from_result(render(s, *sampler, ro));
  };
  if (job.kind != CompareJob::Kind::Reference) return render_scene();

  const ReferenceSetup ref = reference_setup(base, o);
  const fs::path& cache = ref.cache[job.half];
  const PixelRect crop = crop_pixels(base.film.crop_window, base.film.width, base.film.height);
  if (fs::exists(cache)) {
    CompareRender c;
    c.image = read_image_rgb(cache);
    if (c.image.width == crop.width() && c.image.height == crop.height()) {
      say(o, "using the cached reference half " + cache.string());
      c.cached = true, c.file = cache.string();
      return c;
    }
  }
  say(o, "rendering the reference half " + std::to_string(job.half + 1) + "/2 (" + s.sampler.type + ", " +
             std::to_string(s.sampler.spp) + " spp) -> " + cache.string());
  std::error_code ec;
  fs::create_directories(cache.parent_path(), ec);
  CompareRender c = render_scene();
  write_image(cache, c.image, {{"pdrt:reference", "true"}, {"pdrt:key", ref.key}});
  c.file = cache.string();
  return c;
}

}  // namespace pdrt
