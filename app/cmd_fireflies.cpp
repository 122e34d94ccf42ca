// `pdrt fireflies`: counts the fireflies of a rendered image against a reference of the same
// scene (renderer/compare/image_metrics.h): pixels brighter than RATIO times the median
// luminance of their 3x3 neighbourhood where the reference has none.
#include "app/commands.h"
#include "app/numeric_option.h"
#include "renderer/compare/image_metrics.h"
#include "renderer/render/image_output.h"
#include "sampling/core/errors.h"

#include <cstdio>
#include <memory>
#include <string>

namespace pdrt::cli {

void add_fireflies_command(CLI::App& app) {
  struct Opts {
    std::string image, reference;
    double ratio = 10;
    bool list = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand(
      "fireflies", "Count the pixels of an image brighter than RATIO x their 3x3 median where a reference has none.");
  cmd->add_option("image", o->image, "The rendered image (linear EXR)")->required();
  cmd->add_option("--reference,-r", o->reference, "A converged render of the same scene and size (linear EXR)")
      ->required();
  add_real_option(cmd, "--ratio", o->ratio, "Brighter than this many times the 3x3 median (default 10)");
  cmd->add_flag("--list", o->list, "Also print each extra firefly as x y R G B");
  cmd->callback([o] {
    if (!(o->ratio > 1)) throw UsageError("--ratio must be > 1, got " + std::to_string(o->ratio));
    const Image test = read_image_rgb(o->image), ref = read_image_rgb(o->reference);
    if (test.width != ref.width || test.height != ref.height)
      throw InputError(o->image + ": " + std::to_string(test.width) + "x" + std::to_string(test.height) +
                       " but the reference " + o->reference + " is " + std::to_string(ref.width) + "x" +
                       std::to_string(ref.height));
    const FireflyCount c = count_fireflies(test, ref, o->ratio);
    std::printf("%lld fireflies (%lld in the image, %lld in the reference, ratio %g)\n", c.extra, c.test, c.reference,
                o->ratio);
    if (o->list) {
      const auto t = firefly_mask(test, o->ratio), r = firefly_mask(ref, o->ratio);
      for (int y = 0; y < test.height; ++y)
        for (int x = 0; x < test.width; ++x) {
          const std::size_t i = std::size_t(y) * test.width + x;
          if (!t[i] || r[i]) continue;
          std::printf("%d %d %g %g %g\n", x, y, test.rgb[3 * i], test.rgb[3 * i + 1], test.rgb[3 * i + 2]);
        }
    }
  });
}

}  // namespace pdrt::cli
