#include "renderer/compare/compare_plan_file.h"

#include "renderer/compare/json_integer.h"
#include "sampling/core/errors.h"

#include <fstream>
#include <stdexcept>

namespace pdrt {

namespace fs = std::filesystem;
using nlohmann::json;

ComparePlan read_compare_plan(const fs::path& dir) {
  const fs::path file = dir / "plan.json";
  std::ifstream in(file);
  if (!in) throw InputError(file.string() + ": no compare plan here (write one with `pdrt compare SCENE --plan DIR`)");
  ComparePlan p;
  p.dir = dir;
  try {
    const json doc = json::parse(in);
    if (json_integer<int>(doc, "pdrt_plan") != kComparePlanVersion)
      throw std::invalid_argument("plan version " + doc.at("pdrt_plan").dump() + ", this pdrt reads " +
                                  std::to_string(kComparePlanVersion));
    p.id = doc.at("id").get<std::string>();
    p.request = doc.at("request");
    p.scene_hash = std::stoull(doc.at("scene_hash").get<std::string>(), nullptr, 16);
    for (const json& j : doc.at("jobs")) p.jobs.push_back(job_from_json(j));
  } catch (const std::exception& e) {
    throw InputError(file.string() + ": not a pdrt compare plan (" + e.what() + ")");
  }
  return p;
}

CompareJob job_from_json(const json& v) {
  CompareJob j;
  const std::string k = v.at("kind").get<std::string>();
  if (k == "reference")
    j.kind = CompareJob::Kind::Reference;
  else if (k == "uniform")
    j.kind = CompareJob::Kind::Uniform;
  else if (k == "adaptive")
    j.kind = CompareJob::Kind::Adaptive;
  else
    throw std::invalid_argument("unknown job kind \"" + k + "\"");
  j.sampler = v.at("sampler").get<std::string>();
  j.spp = json_integer<int>(v, "spp"), j.seed_index = json_integer<int>(v, "seed_index");
  j.half = json_integer<int>(v, "half"), j.sweep_step = json_integer<int>(v, "sweep_step");
  return j;
}

bool mark_is_for(const json& mark, const ComparePlan& plan, int index) {
  try {
    return mark.at("plan").get<std::string>() == plan.id && json_integer<int>(mark, "index") == index;
  } catch (const std::exception&) {
    return false;
  }
}

CompareRender job_mark_render(const json& v) {
  CompareRender r;
  r.seconds = v.at("seconds").get<double>(), r.build_seconds = v.at("build_seconds").get<double>();
  r.cpu_seconds = v.at("cpu_seconds").get<double>(), r.build_cpu_seconds = v.at("build_cpu_seconds").get<double>();
  r.spp_mean = v.at("spp_mean").get<double>(), r.samples = json_integer<int64_t>(v, "samples");
  r.adaptive_rounds = json_integer<int>(v, "adaptive_rounds"), r.threads = json_integer<int>(v, "threads");
  r.profile.ticks = json_integer<int64_t>(v, "profile_ticks");
  r.profile.sampler_ticks = json_integer<int64_t>(v, "profile_sampler_ticks");
  r.cached = v.at("cached").get<bool>(), r.file = v.at("file").get<std::string>();
  return r;
}

}  // namespace pdrt
