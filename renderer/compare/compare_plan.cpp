#include "renderer/compare/compare_plan.h"

#include "renderer/image/image_output.h"
#include "sampling/core/atomic_file.h"
#include "sampling/core/errors.h"
#include "sampling/core/output_directory.h"
#include "sampling/core/hash.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <numeric>
#include <optional>
#include <sstream>

namespace pdrt {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const char* kind_name(CompareJob::Kind k) {
  switch (k) {
    case CompareJob::Kind::Reference:
      return "reference";
    case CompareJob::Kind::Uniform:
      return "uniform";
    case CompareJob::Kind::Adaptive:
      return "adaptive";
  }
  return "";
}

json job_json(const CompareJob& j) {
  return {{"kind", kind_name(j.kind)},  {"sampler", j.sampler}, {"spp", j.spp},
          {"seed_index", j.seed_index}, {"half", j.half},       {"sweep_step", j.sweep_step},
          {"label", describe(j)}};
}

bool same_job(const CompareJob& a, const CompareJob& b) {
  return a.kind == b.kind && a.sampler == b.sampler && a.spp == b.spp && a.seed_index == b.seed_index &&
         a.half == b.half && a.sweep_step == b.sweep_step;
}

std::string hex(uint64_t v) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "%016llx", (unsigned long long)v);
  return buf;
}

fs::path job_file(const ComparePlan& p, int index, const char* suffix) {
  char name[32];
  std::snprintf(name, sizeof name, "%04d%s", index, suffix);
  return p.dir / "jobs" / name;
}

// Job indices, most expensive first (estimated by job_cost; ties in plan order).
std::vector<int> longest_first(const std::vector<CompareJob>& jobs, const CompareOptions& o) {
  std::vector<int> order(jobs.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return job_cost(jobs[a], o) > job_cost(jobs[b], o); });
  return order;
}

// A path as one POSIX shell word.
std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

void write_script(const fs::path& path, const std::string& text) {
  write_file_atomically(path, [&](std::ostream& os) { os << text; });
  std::error_code ec;
  fs::permissions(path, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec, fs::perm_options::add,
                  ec);
}

// A Slurm job array over DIR/jobs.txt (task i runs its line i + 1: long jobs start first), the
// collect step, and the script that submits both, the collect one after the array succeeded.
void write_slurm_scripts(const ComparePlan& p, const fs::path& pdrt) {
  const std::string dir = shell_quote(fs::absolute(p.dir).string());
  const std::string exe = shell_quote(fs::absolute(pdrt).string());
  const fs::path logs = fs::absolute(p.dir) / "slurm";
  const int n = int(p.jobs.size());
  std::ostringstream run;
  run << "#!/bin/bash\n"
      << "# One array task per job of the plan in " << fs::absolute(p.dir).string() << "; submit with submit.sh.\n"
      << "#SBATCH --job-name=pdrt-jobs\n"
      << "#SBATCH --array=0-" << n - 1 << "\n"
      << "#SBATCH --cpus-per-task=1\n"
      << "#SBATCH --output=" << (logs / "job-%a.log").string() << "\n"
      << "set -euo pipefail\n"
      << "PDRT=${PDRT:-" << exe << "}\n"
      << "index=$(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" " << dir << "/jobs.txt)\n"
      << "exec \"$PDRT\" run-job " << dir << " \"$index\" --quiet --threads \"${SLURM_CPUS_PER_TASK:-1}\"\n";
  write_script(p.dir / "slurm" / "run-jobs.sbatch", run.str());
  std::ostringstream collect;
  collect << "#!/bin/bash\n"
          << "# Writes the report once every job of the plan has finished.\n"
          << "#SBATCH --job-name=pdrt-collect\n"
          << "#SBATCH --output=" << (logs / "collect.log").string() << "\n"
          << "set -euo pipefail\n"
          << "PDRT=${PDRT:-" << exe << "}\n"
          << "exec \"$PDRT\" collect " << dir << " --quiet\n";
  write_script(p.dir / "slurm" / "collect.sbatch", collect.str());
  std::ostringstream submit;
  submit << "#!/bin/bash\n"
         << "# Submits the job array, then the collect step to run after every task succeeded.\n"
         << "set -euo pipefail\n"
         << "cd \"$(dirname \"$0\")\"\n"
         << "array=$(sbatch --parsable run-jobs.sbatch)\n"
         << "sbatch --parsable --dependency=afterok:\"${array%%;*}\" collect.sbatch\n";
  write_script(p.dir / "slurm" / "submit.sh", submit.str());
}

// Job `index`'s mark when the job finished (the mark names this plan and the job, and its
// images are there); nothing otherwise.
std::optional<json> finished_mark(const ComparePlan& plan, int index) {
  std::ifstream in(job_file(plan, index, ".json"));
  if (!in) return std::nullopt;
  json mark;
  try {
    mark = json::parse(in);
    if (!mark_is_for(mark, plan, index)) return std::nullopt;
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (!fs::exists(job_file(plan, index, ".exr"))) return std::nullopt;
  if (plan.jobs[index].kind == CompareJob::Kind::Adaptive && !fs::exists(job_file(plan, index, "-samples.exr")))
    return std::nullopt;
  return mark;
}

}  // namespace

ComparePlan write_compare_plan(const fs::path& dir, const json& request, const CompareOptions& o,
                               const fs::path& pdrt) {
  ComparePlan p;
  p.dir = dir;
  p.request = request;
  p.scene_hash = fnv1a(o.scene_content);
  p.jobs = compare_jobs(o);
  json jobs = json::array();
  for (const CompareJob& j : p.jobs) jobs.push_back(job_json(j));
  p.id = hex(fnv1a(request.dump() + "|" + hex(p.scene_hash) + "|" + jobs.dump()));
  create_output_directory(dir);
  std::error_code ec;
  for (const char* sub : {"jobs", "slurm"}) {
    fs::create_directories(dir / sub, ec);
    if (ec) throw InputError((dir / sub).string() + ": cannot create directory (" + ec.message() + ")");
  }
  const json doc = {{"pdrt_plan", kComparePlanVersion},
                    {"id", p.id},
                    {"request", request},
                    {"scene_hash", hex(p.scene_hash)},
                    {"jobs", jobs}};
  write_file_atomically(dir / "plan.json", [&](std::ostream& os) { os << doc.dump(1) << "\n"; });
  write_file_atomically(dir / "jobs.txt", [&](std::ostream& os) {
    for (int i : longest_first(p.jobs, o)) os << i << "\n";
  });
  write_slurm_scripts(p, pdrt);
  return p;
}

void check_plan_scene(const ComparePlan& plan, const CompareOptions& o) {
  if (fnv1a(o.scene_content) != plan.scene_hash)
    throw InputError(o.scene_label + ": the scene changed since the plan in " + plan.dir.string() +
                     " was written; plan again");
}

bool job_finished(const ComparePlan& plan, int index) { return finished_mark(plan, index).has_value(); }

std::vector<int> unfinished_jobs(const ComparePlan& plan) {
  std::vector<int> left;
  for (int i = 0; i < int(plan.jobs.size()); ++i)
    if (!job_finished(plan, i)) left.push_back(i);
  return left;
}

void run_plan_job(const ComparePlan& plan, int index, const SceneDesc& base, const CompareOptions& o) {
  if (job_finished(plan, index)) return;
  const CompareJob& job = plan.jobs.at(index);
  const CompareRender r = render_job(base, o, job);
  const int W = r.image.width, H = r.image.height;
  const Metadata meta = {{"pdrt:plan", plan.id}, {"pdrt:job", describe(job)}};
  // The mark goes last: a job killed before it is redone, whatever images it left.
  std::error_code ec;
  fs::remove(job_file(plan, index, ".json"), ec);
  write_linear_rgb(job_file(plan, index, ".exr"), W, H, r.image.rgb, meta);
  if (job.kind == CompareJob::Kind::Adaptive) {
    std::vector<float> counts(3 * r.image.samples.size());
    for (std::size_t i = 0; i < r.image.samples.size(); ++i)
      counts[3 * i] = counts[3 * i + 1] = counts[3 * i + 2] = r.image.samples[i];
    write_linear_rgb(job_file(plan, index, "-samples.exr"), W, H, counts, meta);
  }
  const json mark = {{"plan", plan.id},
                     {"index", index},
                     {"job", describe(job)},
                     {"seconds", r.seconds},
                     {"build_seconds", r.build_seconds},
                     {"cpu_seconds", r.cpu_seconds},
                     {"build_cpu_seconds", r.build_cpu_seconds},
                     {"spp_mean", r.spp_mean},
                     {"samples", r.samples},
                     {"adaptive_rounds", r.adaptive_rounds},
                     {"threads", r.threads},
                     {"profile_ticks", r.profile.ticks},
                     {"profile_sampler_ticks", r.profile.sampler_ticks},
                     {"cached", r.cached},
                     {"file", r.file}};
  write_file_atomically(job_file(plan, index, ".json"), [&](std::ostream& os) { os << mark.dump(1) << "\n"; });
}

CompareRender read_plan_job(const ComparePlan& plan, const CompareJob& job) {
  int index = -1;
  for (int i = 0; i < int(plan.jobs.size()) && index < 0; ++i)
    if (same_job(plan.jobs[i], job)) index = i;
  if (index < 0) throw InputError(plan.dir.string() + ": the plan has no job \"" + describe(job) + "\"");
  const fs::path mark_file = job_file(plan, index, ".json");
  const std::optional<json> mark = finished_mark(plan, index);
  if (!mark)
    throw InputError(mark_file.string() + ": job " + std::to_string(index) + " (" + describe(job) +
                     ") has not finished");
  CompareRender r;
  try {
    r = job_mark_render(*mark);
  } catch (const std::exception& e) {
    throw InputError(mark_file.string() + ": not a finished job (" + e.what() + "); run it again");
  }
  r.image = read_image_rgb(job_file(plan, index, ".exr"));
  if (r.file.empty()) r.file = job_file(plan, index, ".exr").string();
  if (job.kind == CompareJob::Kind::Adaptive) {
    const Image counts = read_image_rgb(job_file(plan, index, "-samples.exr"));
    if (counts.width != r.image.width || counts.height != r.image.height)
      throw InputError(job_file(plan, index, "-samples.exr").string() + ": size differs from the job's image");
    r.image.samples.resize(std::size_t(counts.width) * counts.height);
    for (std::size_t i = 0; i < r.image.samples.size(); ++i) r.image.samples[i] = counts.rgb[3 * i];
  }
  return r;
}

std::vector<int> jobs_for_rank(const ComparePlan& plan, const CompareOptions& o, int rank, int size) {
  std::vector<double> load(std::size_t(std::max(1, size)), 0.0);
  std::vector<int> mine;
  for (int i : longest_first(plan.jobs, o)) {
    const int r = int(std::min_element(load.begin(), load.end()) - load.begin());
    load[std::size_t(r)] += job_cost(plan.jobs[i], o);
    if (r == rank) mine.push_back(i);
  }
  return mine;
}

}  // namespace pdrt
