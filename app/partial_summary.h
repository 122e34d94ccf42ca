#pragma once
// What an interrupted render wrote, from its samples AOV: a mean spp hides that some tiles are
// done and the rest black (issue 29), so the summary counts pixels by the samples they got.
#include <string>
#include <vector>

namespace pdrt::cli {

// "40960 of 262144 pixels rendered at 1024 spp (of 4096), 221184 without samples" and the like;
// `target_spp` is what each pixel would have had (0 when not fixed, as under adaptive refinement).
std::string describe_partial_coverage(const std::vector<float>& samples, int target_spp);

}  // namespace pdrt::cli
