// A compare request as the JSON a plan stores (compare_request.h), and back: parsing apart
// from the scene loading of compare_request.cpp, so that tests/fuzz/fuzz_plan.cpp can reach it.
#include "app/compare_request.h"

#include "renderer/compare/json_integer.h"
#include "sampling/core/errors.h"

namespace pdrt::cli {

using nlohmann::json;

json request_json(const CompareRequest& r) {
  json j = {{"scene", r.scene},
            {"label", r.label},
            {"strict", r.strict},
            {"samplers", r.samplers},
            {"spp", r.spp},
            {"cache", r.cache},
            {"reference_spp", r.reference_spp},
            {"threads", r.threads},
            {"seeds", r.seeds},
            {"adaptive", r.adaptive},
            {"adaptive_threshold", r.adaptive_threshold},
            {"adaptive_target_spp", r.adaptive_target_spp},
            {"adaptive_metric", r.adaptive_metric},
            {"adaptive_variance", r.adaptive_variance},
            {"adaptive_decision", r.adaptive_decision},
            {"reconstruction", r.reconstruction},
            {"regularize", r.regularize},
            {"demo_crop", r.demo_crop},
            {"width", r.width ? json(*r.width) : json(nullptr)},
            {"height", r.height ? json(*r.height) : json(nullptr)}};
  return j;
}

CompareRequest request_from_json(const json& j) {
  CompareRequest r;
  r.scene = j.at("scene").get<std::string>(), r.label = j.at("label").get<std::string>();
  r.strict = j.at("strict").get<bool>();
  r.samplers = j.at("samplers").get<std::string>(), r.spp = j.at("spp").get<std::string>();
  r.cache = j.at("cache").get<std::string>();
  r.reference_spp = json_integer<int>(j, "reference_spp"), r.threads = json_integer<int>(j, "threads");
  r.seeds = json_integer<int>(j, "seeds");
  r.adaptive = j.at("adaptive").get<bool>(), r.adaptive_threshold = j.at("adaptive_threshold").get<double>();
  r.adaptive_target_spp = json_integer<int>(j, "adaptive_target_spp");
  r.adaptive_metric = j.at("adaptive_metric").get<std::string>();
  r.adaptive_variance = j.at("adaptive_variance").get<std::string>();
  r.adaptive_decision = j.at("adaptive_decision").get<std::string>();
  r.reconstruction = j.at("reconstruction").get<std::string>();
  r.regularize = j.value("regularize", false);  // absent from plans written before the option
  r.demo_crop = j.value("demo_crop", std::string());
  if (!j.at("width").is_null()) r.width = json_integer<int>(j, "width");
  if (!j.at("height").is_null()) r.height = json_integer<int>(j, "height");
  return r;
}

CompareRequest plan_request(const ComparePlan& plan) {
  try {
    return request_from_json(plan.request);
  } catch (const std::exception& e) {
    throw InputError((plan.dir / "plan.json").string() + ": request: " + e.what());
  }
}

}  // namespace pdrt::cli
