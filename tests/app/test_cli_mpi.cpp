// `mpirun -np N pdrt render` (issue 19, docs/distributed.md): ranks render fixed tile blocks
// and exchange their pixel state, never a floating-point reduce, so the image is the single
// process's bit for bit at any N and thread count, for every sampler, with motion blur, depth
// of field and adaptive refinement, and for splatting and the split decision; a killed rank
// fails the run within seconds, naming the rank; Ctrl-C at mpirun writes the partial image of
// every rank's finished pixels; warnings are printed once, not once per rank.
#include "sampling/samplers/sampler.h"
#include "tests/support/cli_runner.h"
#include "tests/support/process_probe.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fstream>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace pdrt::test;

namespace {

// Open MPI refuses root unless told, and CI runs as root; 3 ranks on 2 cores oversubscribe.
const std::string kMpirun =
    "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 "
    "mpirun --oversubscribe --bind-to none --timeout 120 -np ";

// A moving emitter-lit sphere seen through a thin lens, adaptive from 2 to 16 spp.
std::string scene_text(const std::string& sampler, const std::string& extra_filter, const std::string& decision,
                       bool adaptive = true) {
  return R"({
  "camera": {"position": [0, 1, 4], "look_at": [0, 0.5, 0], "vfov_deg": 45, "aperture_radius": 0.08, "focus_distance": 4},
  "film": {"width": 40, "height": 28, "filter": {"type": "gaussian", "radius": 1.5)" +
         extra_filter + R"(}},
  "sampler": {"type": ")" +
         sampler + R"(", "spp": 16, "seed": 5)" +
         (adaptive ? R"(, "adaptive": {"min_spp": 2, "max_spp": 16, "metric": "relative-error", "decision": ")" +
                         decision + "\"}"
                   : "") +
         R"(},
  "integrator": {"max_depth": 4},
  "materials": {"grey": {"type": "diffuse", "albedo": [0.6, 0.6, 0.6]}, "lamp": {"type": "emitter", "radiance": [6, 6, 6]}},
  "objects": [
    {"type": "quad", "material": "grey", "corner": [-3, 0, 3], "edge1": [6, 0, 0], "edge2": [0, 0, -6]},
    {"type": "sphere", "material": "grey", "center": [-0.8, 0.5, 0], "radius": 0.5,
     "motion": [{"time": 0}, {"time": 0.6, "translate": [0.9, 0, 0]}]},
    {"type": "quad", "material": "lamp", "corner": [-0.5, 2.5, -0.5], "edge1": [1, 0, 0], "edge2": [0, 0, 1]}
  ]
})";
}

std::vector<float> pixels(const fs::path& exr) {
  auto in = OIIO::ImageInput::open(exr.string());
  if (!in) return {};
  const OIIO::ImageSpec& spec = in->spec();
  std::vector<float> px(size_t(spec.width) * spec.height * spec.nchannels);
  in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data());
  return px;
}

int run(const std::string& cmd, std::string* err = nullptr) {
  const fs::path e = scratch_base() / "mpi-stderr.txt";
  const int status = std::system((cmd + " >/dev/null 2>'" + e.string() + "'").c_str());
  if (err) {
    std::ifstream in(e);
    std::stringstream s;
    s << in.rdbuf();
    *err = s.str();
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The single-process render, then 1, 2 and 3 ranks of one thread each: every channel equal.
void expect_same_at_every_rank_count(const std::string& name, const std::string& text) {
  const fs::path dir = scratch_dir("mpi-" + name);
  std::ofstream(dir / "s.json") << text;
  const std::string pdrt = std::string("'") + PDRT_BINARY + "' render '" + (dir / "s.json").string() + "' --quiet -o ";
  ASSERT_EQ(run(pdrt + "'" + (dir / "one.exr").string() + "'"), 0);
  const std::vector<float> one = pixels(dir / "one.exr");
  ASSERT_FALSE(one.empty());
  for (int n : {1, 2, 3}) {
    const fs::path out = dir / ("np" + std::to_string(n) + ".exr");
    std::string err;
    ASSERT_EQ(run(kMpirun + std::to_string(n) + " " + pdrt + "'" + out.string() + "' --threads 1", &err), 0) << err;
    const std::vector<float> got = pixels(out);
    ASSERT_EQ(got.size(), one.size()) << name << " np " << n;
    size_t differ = 0;
    for (size_t i = 0; i < one.size(); ++i) differ += std::memcmp(&one[i], &got[i], sizeof(float)) != 0;
    EXPECT_EQ(differ, 0u) << name << ": " << differ << " of " << one.size() << " values differ at np " << n;
  }
}

// The pid of rank `rank` of the pdrt job writing `out` (found by its command line and
// environment), once it has installed a handler for `signal` (SigCgt in /proc); 0 if none
// shows up within 10 s.
// Waits up to 110 s (mpirun's --timeout is 120): on a loaded machine two ranks can take more
// than 10 s to start and install their handlers; found, it returns at once.
pid_t rank_pid(const fs::path& out, int rank, int signal = 0) {
  for (int tries = 0; tries < 1100; ++tries) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    for (const auto& p : fs::directory_iterator("/proc")) {
      const std::string pid = p.path().filename().string();
      if (pid.find_first_not_of("0123456789") != std::string::npos) continue;
      std::ifstream env(p.path() / "environ", std::ios::binary), cmdline(p.path() / "cmdline", std::ios::binary);
      std::string e((std::istreambuf_iterator<char>(env)), {}), c((std::istreambuf_iterator<char>(cmdline)), {});
      if (c.find(out.string()) == std::string::npos || c.find("mpirun") != std::string::npos ||
          e.find("OMPI_COMM_WORLD_RANK=" + std::to_string(rank) + '\0') == std::string::npos)
        continue;
      if (signal && !pdrt::test::catches_signal(pid_t(std::stoi(pid)), signal)) continue;
      return pid_t(std::stoi(pid));
    }
  }
  return 0;
}

// Stops a 2-rank render of 160 x 112 pixels at 4096 spp (about a minute of work) by sending
// `signal` to mpirun once both ranks are ready for it and have rendered for 2 CPU seconds
// each (the first pass, 8 spp, is 143k samples at about 2 us each); returns mpirun's exit status
// and how long it took to end, and reads the image.
struct Stopped {
  int status = -1;
  double seconds = 0;
  std::string err;
};
Stopped stop_mpirun(const fs::path& dir, int signal) {
  std::ofstream(dir / "s.json") << scene_text("random", "", "shared", false);
  const fs::path out = dir / "o.exr";
  const std::string cmd = "exec env " + kMpirun + "2 '" + PDRT_BINARY + "' render '" + (dir / "s.json").string() +
                          "' --quiet --threads 1 --width 160 --height 112 --spp 4096 --allow-long-render -o '" +
                          out.string() + "' >/dev/null 2>'" + (dir / "err.txt").string() + "'";
  Stopped r;
  const pid_t pid = ::fork();
  if (pid < 0) return r;
  if (pid == 0) {
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  const pid_t rank[2] = {rank_pid(out, 0, SIGTERM), rank_pid(out, 1, SIGTERM)};
  const bool ready = rank[0] && rank[1] && pdrt::test::wait_for_cpu_seconds(rank, 2, 2.0);
  const auto t0 = std::chrono::steady_clock::now();
  ::kill(pid, ready ? signal : SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::ifstream e(dir / "err.txt");
  r.err.assign(std::istreambuf_iterator<char>(e), {});
  if (ready && WIFEXITED(status)) r.status = WEXITSTATUS(status);
  return r;
}

// The partial image of a stopped render: marked partial, every pixel with samples (the passes
// cover the frame: no black strips), and in both ranks' tiles (tile j, 16 x 16 row by row, is
// rank j mod 2's) pixels past the first pass's 8 samples, none at the 4096 asked for.
void expect_partial_image_of_both_ranks(const fs::path& exr) {
  auto in = OIIO::ImageInput::open(exr.string());
  ASSERT_TRUE(in) << "the partial image must be written";
  EXPECT_EQ(in->spec().get_string_attribute("pdrt:partial"), "true");
  EXPECT_NE(in->spec().get_string_attribute("pdrt:spp_complete"), "");
  const int nc = in->spec().nchannels, w = in->spec().width, h = in->spec().height;
  const int s = in->spec().channelindex("samples");
  ASSERT_GE(s, 0);
  std::vector<float> px(std::size_t(w) * h * nc);
  ASSERT_TRUE(in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, px.data()));
  int64_t past_first[2] = {0, 0}, empty = 0, complete = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float n = px[(std::size_t(y) * w + x) * nc + s];
      past_first[((y / 16) * ((w + 15) / 16) + x / 16) % 2] += n > 8;
      empty += n == 0;
      complete += n >= 4096;
    }
  EXPECT_GT(past_first[0], 0);
  EXPECT_GT(past_first[1], 0);
  EXPECT_EQ(empty, 0);
  EXPECT_EQ(complete, 0);
}

}  // namespace

TEST(CliMpi, RanksRenderTheSingleProcessImageForEverySampler) {
  for (const std::string& sampler : pdrt::sampler_names())
    expect_same_at_every_rank_count(sampler, scene_text(sampler, "", "shared"));
}

TEST(CliMpi, RanksRenderTheSingleProcessImageWhenSplattingAndSplitDeciding) {
  expect_same_at_every_rank_count("splat", scene_text("poisson", R"(, "reconstruction": "splat")", "shared"));
  expect_same_at_every_rank_count("split", scene_text("sobol", "", "split"));
}

// 16 spp in two passes (8, 16): without splatting the ranks exchange their tiles only
// after the last, with splatting after every wave of every pass; the same image either way.
TEST(CliMpi, RanksRenderTheSingleProcessImageOverProgressivePasses) {
  expect_same_at_every_rank_count("passes", scene_text("sobol", "", "", false));
  expect_same_at_every_rank_count("passes-splat", scene_text("poisson", R"(, "reconstruction": "splat")", "", false));
}

// A crop window that cuts tiles: each rank sends rank 0 only its tiles' pixels inside the crop,
// into their place in the crop's image; with splatting, the tiles of the margin around the
// crop are rendered and their splats reach it. The image is the single process's.
TEST(CliMpi, RanksRenderTheSingleProcessImageOfACropWindow) {
  for (const bool splat : {false, true}) {
    std::string text = scene_text("sobol", splat ? R"(, "reconstruction": "splat")" : "", "", false);
    const std::string from = R"("width": 40, "height": 28,)";
    text.replace(text.find(from), from.size(), from + R"( "crop_window": [0.13, 0.81, 0.2, 0.9],)");
    expect_same_at_every_rank_count(splat ? "crop-splat" : "crop", text);
  }
}

// poisson-ip: pixels trace varying counts of one image-plane pattern, splatted over the tiles'
// borders and divided by the expected weight, over two passes.
TEST(CliMpi, RanksRenderTheSingleProcessImageWithTheImagePlaneSampler) {
  expect_same_at_every_rank_count("image-plane", scene_text("poisson-ip", R"(, "reconstruction": "splat")", "", false));
}

// At 3 spp the time estimate's calibration keeps its samples as the pixels' first, each rank
// in blocks of its own tiles: on a 32 x 16 film of two tiles it takes every pixel of the
// second rank's, whose tile then takes no sample in the pass and must still reach rank 0. The
// image is the single process's.
TEST(CliMpi, RanksRenderTheSingleProcessImageWithTheCalibrationsSamplesKept) {
  std::string text = scene_text("poisson", "", "", false);
  for (const auto& [from, to] : {std::pair<std::string, std::string>{R"("spp": 16)", R"("spp": 3)"},
                                 {R"("width": 40, "height": 28)", R"("width": 32, "height": 16)"}})
    text.replace(text.find(from), from.size(), to);
  expect_same_at_every_rank_count("calibration-kept", text);
}

// Runs `pdrt render` of `scene` under 2 ranks with rank `rank`'s PDRT_IMAGE_MODULE naming a
// file that does not exist, writing `out`; returns mpirun's exit status and stderr.
int render_without_module_on_rank(const fs::path& dir, const fs::path& scene, const fs::path& out, int rank,
                                  std::string* err) {
  const fs::path wrapper = dir / "wrapper.sh";
  std::ofstream(wrapper) << "#!/bin/sh\nif [ \"$OMPI_COMM_WORLD_RANK\" = " << rank
                         << " ]; then export PDRT_IMAGE_MODULE=/nonexistent/libpdrt_image.so; fi\nexec \"$@\"\n";
  fs::permissions(wrapper, fs::perms::owner_all);
  return run(kMpirun + "2 '" + wrapper.string() + "' '" + PDRT_BINARY + "' render '" + scene.string() +
                 "' --quiet --threads 1 -o '" + out.string() + "'",
             err);
}

// Only rank 0 writes, so only rank 0 loads the image module (OpenImageIO's libraries: 0.2 s of
// CPU and 40 MB a process): the other ranks render without it, and the image is the single
// process's.
TEST(CliMpi, RanksButTheFirstRenderWithoutTheImageModule) {
  const fs::path dir = scratch_dir("mpi-no-module");
  std::ofstream(dir / "s.json") << scene_text("sobol", "", "", false);
  ASSERT_EQ(run("'" + std::string(PDRT_BINARY) + "' render '" + (dir / "s.json").string() + "' --quiet -o '" +
                (dir / "one.exr").string() + "'"),
            0);
  std::string err;
  ASSERT_EQ(render_without_module_on_rank(dir, dir / "s.json", dir / "np2.exr", 1, &err), 0) << err;
  const std::vector<float> one = pixels(dir / "one.exr"), two = pixels(dir / "np2.exr");
  ASSERT_FALSE(one.empty());
  ASSERT_EQ(two.size(), one.size());
  EXPECT_EQ(std::memcmp(one.data(), two.data(), one.size() * sizeof(float)), 0);
}

// Rank 0 alone finds the module missing: it says so and ends the job at once (the others would
// otherwise wait for it in the render's first exchange), and no image is written.
TEST(CliMpi, AMissingImageModuleOnRankZeroEndsTheJobNamingIt) {
  const fs::path dir = scratch_dir("mpi-no-module-lead");
  std::ofstream(dir / "s.json") << scene_text("sobol", "", "", false);
  std::string err;
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_NE(render_without_module_on_rank(dir, dir / "s.json", dir / "o.exr", 0, &err), 0);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 60);
  EXPECT_NE(err.find("cannot load the image module /nonexistent/libpdrt_image.so"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(dir / "o.exr"));
}

TEST(CliMpi, StatsListEveryRanksShare) {
  const fs::path dir = scratch_dir("mpi-stats");
  std::ofstream(dir / "s.json") << scene_text("jitter", "", "shared");
  ASSERT_EQ(
      run(kMpirun + "2 '" + PDRT_BINARY + "' render '" + (dir / "s.json").string() + "' --quiet --threads 1 -o '" +
          (dir / "o.exr").string() + "' --stats '" + (dir / "stats.json").string() + "'"),
      0);
  std::ifstream in(dir / "stats.json");
  std::stringstream s;
  s << in.rdbuf();
  const std::string j = s.str();
  EXPECT_NE(j.find("\"ranks\""), std::string::npos) << j;
  EXPECT_NE(j.find("\"rank\": 1"), std::string::npos) << j;
  EXPECT_NE(j.find("\"bytes_sent\""), std::string::npos) << j;
}

// A fixed-spp render's films are read by no other rank: each rank's tiles go to no one until
// the end, when the other rank sends rank 0 the image values of its tiles' pixels, 48 bytes a
// pixel (not their accumulators, 224). 16 spp in two passes: each rank sends one byte per pass
// (whether it was stopped) and its 32 bytes of sample counts to the other; rank 1 also its
// pixels. (The image is the single-process one: RanksRenderTheSingleProcessImageOverProgressivePasses.)
TEST(CliMpi, AFixedSppRenderSendsRankZeroTheImageValuesOfTheOtherRanksTiles) {
  const fs::path dir = scratch_dir("mpi-to-lead");
  std::ofstream(dir / "s.json") << scene_text("sobol", "", "", false);
  ASSERT_EQ(
      run(kMpirun + "2 '" + PDRT_BINARY + "' render '" + (dir / "s.json").string() + "' --quiet --threads 1 -o '" +
          (dir / "o.exr").string() + "' --stats '" + (dir / "stats.json").string() + "'"),
      0);
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(dir / "stats.json"));
  ASSERT_EQ(j.at("ranks").size(), 2u);
  EXPECT_EQ(j["ranks"][0]["bytes_sent"].get<int64_t>(), 2 + 32);
  const int64_t image = j["ranks"][1]["bytes_sent"].get<int64_t>() - 2 - 32;
  EXPECT_EQ(image % 48, 0) << image;
  // The 40 x 28 film has six tiles (16 x 16 pixels, cut at the edges): rank 1 renders three.
  EXPECT_GE(image / 48, 96 + 128 + 192) << "three of the six tiles";
  EXPECT_LE(image / 48, 256 + 256 + 192);
  // Rank 0's counts cover rank 1's tiles too, which its film does not hold.
  EXPECT_EQ(j["samples"].get<int64_t>(), 40 * 28 * 16);
}

// After the first all-gather every rank holds the same films, so an adaptive round sends only
// the tiles it refined: at 160 x 96 the black sky's tiles never are. Rank 1 owns 30 of the 60
// tiles (7680 pixels, 224 bytes each); sending all of them after round 0 and after every round
// would be (rounds + 1) x 1,720,320 bytes. The image stays the single process's.
TEST(CliMpi, AdaptiveRoundsSendOnlyTheTilesTheyRefined) {
  const fs::path dir = scratch_dir("mpi-refined-tiles");
  std::ofstream(dir / "s.json") << scene_text("sobol", "", "shared");
  const std::string pdrt = std::string("'") + PDRT_BINARY + "' render '" + (dir / "s.json").string() +
                           "' --quiet --threads 1 --width 160 --height 96 -o ";
  ASSERT_EQ(run(pdrt + "'" + (dir / "one.exr").string() + "'"), 0);
  ASSERT_EQ(run(kMpirun + "2 " + pdrt + "'" + (dir / "np2.exr").string() + "' --stats '" +
                (dir / "stats.json").string() + "'"),
            0);
  const std::vector<float> one = pixels(dir / "one.exr"), two = pixels(dir / "np2.exr");
  ASSERT_EQ(two.size(), one.size());
  EXPECT_EQ(std::memcmp(one.data(), two.data(), one.size() * sizeof(float)), 0);
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(dir / "stats.json"));
  const int64_t rounds = j.at("adaptive").at("rounds").get<int64_t>();
  ASSERT_GE(rounds, 2);
  const int64_t sent = j.at("ranks").at(1).at("bytes_sent").get<int64_t>(), full = 7680 * 224;
  EXPECT_GT(sent, full);  // round 0's exchange sends every tile
  EXPECT_LT(double(sent), 0.6 * double((rounds + 1) * full)) << sent << " bytes in " << rounds << " rounds";
}

TEST(CliMpi, AKilledRankFailsTheRunWithinSecondsNamingIt) {
  const fs::path dir = scratch_dir("mpi-kill");
  // Long enough to be killed in the middle: 4096 spp.
  std::ofstream(dir / "s.json") << scene_text("random", "", "shared", false);
  const std::string cmd = kMpirun + "2 '" + PDRT_BINARY + "' render '" + (dir / "s.json").string() +
                          "' --quiet --threads 1 --spp 4096 --allow-long-render -o '" + (dir / "o.exr").string() + "'";
  std::string err;
  // Killed once it is rendering: its SIGTERM handler is installed after MPI_Init, and a rank
  // killed before MPI_Init left mpirun waiting for its --timeout on a loaded machine. The time
  // counts from the kill, not from a start-up that a loaded machine stretches.
  std::atomic<bool> killed{false};
  std::chrono::steady_clock::time_point t_kill;
  std::thread killer([&] {
    pid_t rank1 = rank_pid(dir / "o.exr", 1, SIGTERM);
    if (rank1 && pdrt::test::wait_for_cpu_seconds(&rank1, 1, 0.2)) {
      t_kill = std::chrono::steady_clock::now();
      killed = ::kill(rank1, SIGKILL) == 0;
    }
  });
  const int code = run(cmd, &err);
  killer.join();
  ASSERT_TRUE(killed) << "rank 1 was not found rendering: " << err;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_kill).count();
  EXPECT_NE(code, 0);
  EXPECT_LT(seconds, 30);
  EXPECT_NE(err.find("rank 1"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(dir / "o.exr"));  // no partial output
}

// Ctrl-C at mpirun: Open MPI 4.1's mpirun sends the ranks SIGTERM and SIGKILL a second later
// (odls_base_sigkill_timeout); the ranks stop at their next pixel, exchange what they
// finished, and rank 0 writes the partial image in time. mpirun itself, having ended the job,
// exits 1 whatever the ranks return.
TEST(CliMpi, CtrlCAtMpirunWritesThePartialImageOfEveryRank) {
  const fs::path dir = scratch_dir("mpi-sigint");
  const Stopped r = stop_mpirun(dir, SIGINT);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_LT(r.seconds, 10) << r.err;
  expect_partial_image_of_both_ranks(dir / "o.exr");
}

// SIGUSR1 to mpirun reaches the ranks without ending the job: the same partial image, and
// mpirun passes on rank 0's exit status, 130 as for one interrupted process.
TEST(CliMpi, SigusrOneToMpirunWritesThePartialImageAndExits130) {
  const fs::path dir = scratch_dir("mpi-sigusr1");
  const Stopped r = stop_mpirun(dir, SIGUSR1);
  EXPECT_EQ(r.status, 130) << r.err;
  EXPECT_LT(r.seconds, 10) << r.err;
  expect_partial_image_of_both_ranks(dir / "o.exr");
}

// A warning every rank meets (degenerate triangles in the scene) is printed once, by rank 0.
TEST(CliMpi, WarningsArePrintedOnce) {
  const fs::path dir = scratch_dir("mpi-warn");
  std::string text = scene_text("jitter", "", "shared", false);
  const std::string mesh =
      R"({"type": "mesh", "material": "grey", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "indices": [0, 1, 2, 0, 0, 1]},)";
  text.insert(text.find("\"objects\": [") + 12, "\n    " + mesh);
  std::ofstream(dir / "s.json") << text;
  const std::string warning = "warning: skipped 1 degenerate triangle";
  for (int n : {1, 2, 3}) {
    std::string err;
    ASSERT_EQ(run(kMpirun + std::to_string(n) + " '" + PDRT_BINARY + "' render '" + (dir / "s.json").string() +
                      "' --quiet --threads 1 --spp 4 -o '" + (dir / "o.exr").string() + "'",
                  &err),
              0)
        << err;
    std::size_t count = 0;
    for (std::size_t at = err.find(warning); at != std::string::npos; at = err.find(warning, at + 1)) ++count;
    EXPECT_EQ(count, 1u) << "np " << n << ": " << err;
  }
}
