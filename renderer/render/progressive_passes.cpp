#include "renderer/render/progressive_passes.h"

#include "renderer/render/tile_passes.h"
#include "sampling/core/progress.h"

#include <string>

namespace pdrt {

int64_t render_progressive(TilePasses& passes, int64_t spp, Progress& progress,
                           const std::function<void(int64_t)>& on_pass, FilmsTo last) {
  const int n = pass_count(spp);
  int64_t done = 0;
  for (int k = 1; done < spp; ++k) {
    const int64_t end = next_pass_end(done, spp);
    progress.relabel("render, pass " + std::to_string(k) + " of " + std::to_string(n) + " (" + std::to_string(end) +
                     " spp)");
    if (!passes.run([end](int, int) { return end; }, progress, end == spp ? last : FilmsTo::None)) break;
    done = end;
    if (on_pass) on_pass(done);
  }
  return done;
}

}  // namespace pdrt
