// The files `pdrt run-job` and `pdrt collect` read from a plan directory: the input is read as
// DIR/plan.json (then its request, as those commands rebuild it) and, the same bytes, as a
// finished job's mark DIR/jobs/NNNN.json.
#include "app/compare_request.h"
#include "renderer/compare/compare_plan_file.h"
#include "sampling/core/errors.h"
#include "tests/fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text = pdrt::fuzz::as_text(data, size);
  pdrt::fuzz::write_input(text, "plan.json");
  try {
    const pdrt::ComparePlan plan = pdrt::read_compare_plan(pdrt::fuzz::scratch_dir());
    pdrt::cli::plan_request(plan);
  } catch (const pdrt::InputError&) {}
  const nlohmann::json mark = nlohmann::json::parse(text, nullptr, false);
  if (!mark.is_discarded()) {
    pdrt::mark_is_for(mark, pdrt::ComparePlan{}, 0);
    try {
      pdrt::job_mark_render(mark);
    } catch (const std::exception&) {}
  }
  return 0;
}
