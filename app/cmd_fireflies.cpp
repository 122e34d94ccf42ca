// `pdrt fireflies`: counts the fireflies of a rendered image against a reference of the same
// scene (renderer/compare/image_metrics.h): pixels brighter than RATIO times the median
// luminance of their 3x3 neighbourhood where the reference has none, and the specks: pixels
// brighter than SPECK_RATIO times the reference's.
#include "app/commands.h"
#include "app/numeric_option.h"
#include "renderer/compare/image_metrics.h"
#include "renderer/image/image_output.h"
#include "sampling/core/errors.h"

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace pdrt::cli {

void add_fireflies_command(CLI::App& app) {
  struct Opts {
    std::string image, reference;
    double ratio = 10, floor = 0, speck_ratio = 3, speck_floor = 0.05;
    bool list = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand(
      "fireflies", "Count the pixels of an image brighter than RATIO x their 3x3 median where a reference has none.");
  cmd->add_option("image", o->image, "The rendered image (linear EXR)")->required();
  cmd->add_option("--reference,-r", o->reference, "A converged render of the same scene and size (linear EXR)")
      ->required();
  add_real_option(cmd, "--ratio", o->ratio, "Brighter than this many times the 3x3 median (default 10)");
  add_real_option(cmd, "--floor", o->floor,
                  "A firefly is also brighter than its 3x3 median by more than this luminance (default 0: the "
                  "ratio alone)");
  add_real_option(cmd, "--speck-ratio", o->speck_ratio,
                  "A speck is brighter than this many times the reference's pixel (default 3)");
  add_real_option(cmd, "--speck-floor", o->speck_floor,
                  "... and brighter than it by more than this luminance (default 0.05)");
  cmd->add_flag("--list", o->list, "Also print each extra firefly, then each speck, as x y R G B");
  cmd->callback([o] {
    if (!(o->ratio > 1)) throw UsageError("--ratio must be > 1, got " + std::to_string(o->ratio));
    if (!(o->speck_ratio > 1)) throw UsageError("--speck-ratio must be > 1, got " + std::to_string(o->speck_ratio));
    if (!(o->floor >= 0)) throw UsageError("--floor must be >= 0, got " + std::to_string(o->floor));
    if (!(o->speck_floor >= 0)) throw UsageError("--speck-floor must be >= 0, got " + std::to_string(o->speck_floor));
    const Image test = read_image_rgb(o->image), ref = read_image_rgb(o->reference);
    if (test.width != ref.width || test.height != ref.height)
      throw InputError(o->image + ": " + std::to_string(test.width) + "x" + std::to_string(test.height) +
                       " but the reference " + o->reference + " is " + std::to_string(ref.width) + "x" +
                       std::to_string(ref.height));
    const FireflyCount c = count_fireflies(test, ref, o->ratio, o->floor);
    const std::vector<unsigned char> specks = speck_mask(test, ref, o->speck_ratio, o->speck_floor);
    long long n_specks = 0;
    for (unsigned char m : specks) n_specks += m;
    std::printf(
        "%lld fireflies (%lld in the image, %lld in the reference, ratio %g, floor %g); "
        "%lld specks (over %g x the reference and +%g)\n",
        c.extra, c.test, c.reference, o->ratio, o->floor, n_specks, o->speck_ratio, o->speck_floor);
    if (o->list) {
      const auto t = firefly_mask(test, o->ratio, o->floor), r = firefly_mask(ref, o->ratio, o->floor);
      auto print = [&](const char* what, std::size_t i) {
        std::printf("%s %d %d %g %g %g\n", what, int(i % test.width), int(i / test.width), test.rgb[3 * i],
                    test.rgb[3 * i + 1], test.rgb[3 * i + 2]);
      };
      for (std::size_t i = 0; i < t.size(); ++i)
        if (t[i] && !r[i]) print("firefly", i);
      for (std::size_t i = 0; i < specks.size(); ++i)
        if (specks[i]) print("speck", i);
    }
  });
}

}  // namespace pdrt::cli
