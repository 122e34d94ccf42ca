// `pdrt render`: the main job — render a scene file to an image (plus AOVs and stats).
#include "atomic_file.h"
#include "commands.h"
#include "errors.h"
#include "image_output.h"
#include "renderer.h"
#include "scene_loader.h"

#include <nlohmann/json.hpp>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

namespace pdrt::cli {

namespace {

std::atomic<bool> g_cancel{false};
extern "C" void on_sigint(int) { g_cancel.store(true); }

}  // namespace

void add_render_command(CLI::App& app) {
  struct Opts {
    std::string scene, out, stats, sampler;
    std::optional<int> spp, width, height;
    std::optional<uint64_t> seed;
    int threads = 0;
    bool quiet = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("render", "Render a scene file (docs/scene-format.md) to an image.");
  cmd->add_option("scene", o->scene, "Scene JSON file")->required();
  cmd->add_option("--out,-o", o->out, "Output image: .exr (linear + AOVs), .png/.jpg (sRGB), .tif (linear)")->required();
  cmd->add_option("--spp", o->spp, "Samples per pixel (overrides sampler.spp)");
  cmd->add_option("--sampler", o->sampler, "random | jitter | poisson | sobol (overrides sampler.type)");
  cmd->add_option("--seed", o->seed, "Sampler seed (overrides sampler.seed)");
  cmd->add_option("--threads,-t", o->threads, "Worker threads (0 = all cores)")->default_val(0);
  cmd->add_option("--width", o->width, "Image width in pixels (overrides film.width)");
  cmd->add_option("--height", o->height, "Image height in pixels (overrides film.height)");
  cmd->add_option("--stats", o->stats, "Write render statistics as JSON to this file");
  cmd->add_flag("--quiet,-q", o->quiet, "No progress or summary on stderr");
  cmd->callback([o] {
    // Validate every argument before loading or rendering anything.
    if (o->spp && *o->spp < 1) throw UsageError("--spp must be >= 1, got " + std::to_string(*o->spp));
    if (o->width && *o->width < 1) throw UsageError("--width must be >= 1, got " + std::to_string(*o->width));
    if (o->height && *o->height < 1) throw UsageError("--height must be >= 1, got " + std::to_string(*o->height));
    if (o->width && *o->width > 65536) throw UsageError("--width must be <= 65536, got " + std::to_string(*o->width));
    if (o->height && *o->height > 65536) throw UsageError("--height must be <= 65536, got " + std::to_string(*o->height));
    if (o->threads < 0) throw UsageError("--threads must be >= 0, got " + std::to_string(o->threads));
    if (!o->sampler.empty()) {
      bool known = false;
      for (const auto& n : sampler_names()) known = known || n == o->sampler;
      if (!known) throw UsageError("--sampler: unknown sampler \"" + o->sampler + "\" (random, jitter, poisson, sobol)");
    }
    check_image_extension(o->out);

    SceneDesc scene = load_scene(o->scene);
    if (o->spp) scene.sampler.spp = *o->spp;
    if (!o->sampler.empty()) scene.sampler.type = o->sampler;
    if (o->seed) scene.sampler.seed = *o->seed;
    if (o->width) scene.film.width = *o->width;
    if (o->height) scene.film.height = *o->height;
    check_film_memory(scene.film.width, scene.film.height);
    check_writable(o->out);
    if (!o->stats.empty()) check_writable(o->stats);

    auto sampler = make_scene_sampler(scene.sampler);
    RenderOptions ro;
    ro.threads = o->threads;
    ro.quiet = o->quiet;
    ro.cancel = &g_cancel;
    auto previous = std::signal(SIGINT, on_sigint);
    RenderResult r = render(scene, *sampler, ro);
    std::signal(SIGINT, previous);

    Metadata md = {{"Software", std::string("pdrt ") + PDRT_VERSION},
                   {"pdrt:version", PDRT_VERSION},
                   {"pdrt:scene", o->scene},
                   {"pdrt:sampler", scene.sampler.type},
                   {"pdrt:spp", std::to_string(scene.sampler.spp)},
                   {"pdrt:seed", std::to_string(scene.sampler.seed)},
                   {"pdrt:render_seconds", std::to_string(r.stats.seconds)},
                   {"pdrt:partial", r.stats.partial ? "true" : "false"}};
    write_image(o->out, r.image, md);
    if (!o->stats.empty()) {
      nlohmann::json j;
      j["scene"] = o->scene;
      j["sampler"] = scene.sampler.type;
      j["seed"] = scene.sampler.seed;
      j["width"] = scene.film.width;
      j["height"] = scene.film.height;
      j["spp"] = scene.sampler.spp;
      j["seconds"] = r.stats.seconds;
      j["rays"] = r.stats.rays;
      j["mrays_per_second"] = r.stats.seconds > 0 ? r.stats.rays / r.stats.seconds * 1e-6 : 0.0;
      j["samples"] = r.stats.samples;
      j["spp_mean"] = r.stats.spp_mean;
      j["triangles"] = r.stats.triangles;
      j["threads"] = o->threads;
      j["partial"] = r.stats.partial;
      write_file_atomically(o->stats, [&](std::ostream& os) { os << j.dump(2) << "\n"; });
    }
    if (!o->quiet)
      std::fprintf(stderr, "pdrt render: %s %dx%d, %s, %.1f spp, %.2f s, %.2f Mrays/s%s\n", o->out.c_str(),
                   scene.film.width, scene.film.height, scene.sampler.type.c_str(), r.stats.spp_mean, r.stats.seconds,
                   r.stats.seconds > 0 ? r.stats.rays / r.stats.seconds * 1e-6 : 0.0,
                   r.stats.partial ? " (interrupted: partial image)" : "");
    if (r.stats.partial && g_cancel.load()) throw InterruptedError("interrupted; wrote the partial image " + o->out);
  });
}

}  // namespace pdrt::cli
