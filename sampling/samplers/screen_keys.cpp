#include "sampling/samplers/screen_keys.h"

#include "sampling/core/cache_dir.h"
#include "sampling/core/checksummed_file.h"
#include "sampling/core/hash.h"
#include "sampling/core/rng.h"
#include "sampling/core/warnings.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <tuple>

namespace pdrt {
namespace {

constexpr double kFixed = 0x1.0p-32;
constexpr int kRadius = 3;  // the blur kernel's half width: 3 sigma

// Counter-based draws, so the optimisation is a pure function of its options.
struct Draws {
  uint64_t key, n = 0;
  uint64_t next() { return hash_combine(key, n++); }
  double unit() { return double(next() >> 11) * 0x1.0p-53; }
};

// Area of {u in [0,1]^2 : n . u > c}: the square clipped by the half-plane (shoelace).
double half_plane_area(double nx, double ny, double c) {
  const std::array<double, 2> square[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::array<double, 2> poly[8];
  int m = 0;
  for (int i = 0; i < 4; ++i) {
    const auto a = square[i], b = square[(i + 1) % 4];
    const double fa = nx * a[0] + ny * a[1] - c, fb = nx * b[0] + ny * b[1] - c;
    if (fa > 0) poly[m++] = a;
    if ((fa > 0) != (fb > 0)) {
      const double t = fa / (fa - fb);
      poly[m++] = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
    }
  }
  double twice = 0;
  for (int i = 0; i < m; ++i) twice += poly[i][0] * poly[(i + 1) % m][1] - poly[i][1] * poly[(i + 1) % m][0];
  return std::fabs(twice) / 2;
}

ScreenKey random_key(Draws& d, std::size_t tables, int dim) {
  const uint64_t a = d.next(), b = d.next();
  ScreenKey k;
  k.x[0] = uint32_t(a), k.x[1] = dim == 2 ? uint32_t(a >> 32) : 0;
  k.table = uint16_t((b >> 32) * tables >> 32);
  k.swap = dim == 2 ? uint16_t(b & 1) : 0;
  return k;
}

// The Gaussian (sigma 1 px) and its autocorrelation, which maps an error image to the
// gradient of its blurred energy.
struct Kernels {
  static constexpr int W = 2 * kRadius + 1, W2 = 4 * kRadius + 1;
  double w[W][W], ww[W2][W2], sum_sq = 0;
  Kernels() {
    // exp(-k / 2) for k = a^2 + b^2 <= 18, spelled out (libm's exp is not the same bits everywhere).
    static constexpr double kExpHalf[19] = {
        0x1.0000000000000p+0,  0x1.368b2fc6f960ap-1,  0x1.78b56362cef38p-2,  0x1.c8f87724b5c1dp-3,
        0x1.152aaa3bf81ccp-3,  0x1.50385c094f425p-4,  0x1.97db0ccceb0afp-5,  0x1.eec1018e4ff66p-6,
        0x1.2c155b8213cf4p-6,  0x1.6c0504695c417p-7,  0x1.b993fe00d5376p-8,  0x1.0bd4a5aca7728p-8,
        0x1.44e51f113d4d6p-9,  0x1.8a1e18a954ffap-10, 0x1.de16b9c24a98fp-11, 0x1.21f9ba40f31d5p-11,
        0x1.5fc21041027adp-12, 0x1.aab43fb3940a1p-13, 0x1.02cf22526545ap-13};
    double s = 0;
    for (int a = -kRadius; a <= kRadius; ++a)
      for (int b = -kRadius; b <= kRadius; ++b) s += w[a + kRadius][b + kRadius] = kExpHalf[a * a + b * b];
    for (auto& r : w)
      for (double& v : r) v /= s, sum_sq += v * v;
    for (int a = -2 * kRadius; a <= 2 * kRadius; ++a)
      for (int b = -2 * kRadius; b <= 2 * kRadius; ++b) {
        double v = 0;
        for (int c = -kRadius; c <= kRadius; ++c)
          for (int d = -kRadius; d <= kRadius; ++d) {
            const int e = a - c, f = b - d;
            if (std::abs(e) <= kRadius && std::abs(f) <= kRadius)
              v += w[c + kRadius][d + kRadius] * w[e + kRadius][f + kRadius];
          }
        ww[a + 2 * kRadius][b + 2 * kRadius] = v;
      }
  }
};

}  // namespace

StepIntegrand random_step(int dim, uint64_t key) {
  Draws d{key};
  StepIntegrand f{};
  if (dim == 2) {
    // A direction from the square (n need not be a unit vector): arithmetic only, no libm,
    // whose versions round differently on different processors, so every rank optimises the
    // same tile.
    double nx, ny;
    do nx = 2 * d.unit() - 1, ny = 2 * d.unit() - 1;
    while (nx * nx + ny * ny > 1 || nx * nx + ny * ny < 1e-6);
    const double px = d.unit(), py = d.unit();
    f.n[0] = nx, f.n[1] = ny;
    f.c = f.n[0] * px + f.n[1] * py;
    f.integral = half_plane_area(f.n[0], f.n[1], f.c);
  } else {
    f.n[0] = -1, f.n[1] = 0;  // {u < c} as {-u > -c}
    const double c = d.unit();
    f.c = -c, f.integral = c;
  }
  const uint64_t g = d.next();
  f.g[0] = uint32_t(g), f.g[1] = dim == 2 ? uint32_t(g >> 32) : 0;
  return f;
}

double key_error(const uint32_t* table, int dim, int spp, const ScreenKey& k, const StepIntegrand& f) {
  double sum = 0;
  for (int i = 0; i < spp; ++i) {
    double s = 0;
    for (int a = 0; a < dim; ++a) {
      const uint32_t v = table[std::size_t(i) * dim + (k.swap ? 1 - a : a)] ^ k.x[a] ^ f.g[a];
      s += f.n[a] * (double(v) * kFixed);
    }
    sum += s > f.c;
  }
  return sum / spp - f.integral;
}

ScreenKeyTile optimize_screen_keys(const std::vector<const uint32_t*>& tables, int dim, int spp,
                                   const ScreenKeyOptions& o, double* energy_ratio) {
  const int N = o.size, K = N * N, J = o.integrands;
  Draws draws{o.seed ^ (uint64_t(dim) << 56) ^ uint64_t(spp)};
  std::vector<ScreenKey> cand(static_cast<std::size_t>(K), ScreenKey{});
  for (ScreenKey& k : cand) k = random_key(draws, tables.size(), dim);
  std::vector<StepIntegrand> steps(static_cast<std::size_t>(J), StepIntegrand{});
  for (int j = 0; j < J; ++j) steps[std::size_t(j)] = random_step(dim, hash_combine(draws.key, 0x100000000ull + j));
  // The candidates' errors on every integrand (float: the search only compares energies).
  std::vector<float> err(std::size_t(K) * J);
  // Isolated: the caller holds cached_screen_keys' lock, and a thread waiting here must not
  // pick up an outer task that asks for a tile and waits on that lock.
  tbb::this_task_arena::isolate([&] {
    tbb::parallel_for(0, K, [&](int c) {
      for (int j = 0; j < J; ++j)
        err[std::size_t(c) * J + j] =
            float(key_error(tables[cand[std::size_t(c)].table], dim, spp, cand[std::size_t(c)], steps[std::size_t(j)]));
    });
  });
  // Every integrand weighs alike: its errors in units of their RMS over the candidates.
  for (int j = 0; j < J; ++j) {
    double ss = 0;
    for (int c = 0; c < K; ++c) ss += double(err[std::size_t(c) * J + j]) * err[std::size_t(c) * J + j];
    const float scale = ss > 0 ? float(1 / std::sqrt(ss / K)) : 0.0f;
    for (int c = 0; c < K; ++c) err[std::size_t(c) * J + j] *= scale;
  }
  static const Kernels kern;
  const auto wrap = [N](int a) { return ((a % N) + N) % N; };
  // Each pixel starts with a key of its own; the search only swaps them, so the tile holds the
  // same random keys in any order and every pixel's values stay a uniform draw across the
  // image, not only over seeds (a search that could pick keys would favour the points whose
  // errors are small on the training steps, and reuse them).
  std::vector<int> pick(std::size_t(N) * N);
  for (int p = 0; p < N * N; ++p) pick[std::size_t(p)] = p;
  // B: the blurred error images (pixel-major, J per pixel); C: B blurred again. Swapping the
  // keys of p and q changes p's errors by d and q's by -d, and the energy sum_j |B_j|^2 by
  // 2 d . (C_p - C_q) + |d|^2 (2 sum w^2 - 2 (w * w)(p - q)).
  std::vector<float> B(std::size_t(N) * N * J, 0.0f), C(B.size(), 0.0f);
  const auto add_around = [&](std::vector<float>& img, int px, int py, int r, const float* d, float sign, bool twice) {
    for (int a = -r; a <= r; ++a)
      for (int b = -r; b <= r; ++b) {
        const float w = sign * float(twice ? kern.ww[a + r][b + r] : kern.w[a + r][b + r]);
        float* out = &img[(std::size_t(wrap(py + a)) * N + wrap(px + b)) * J];
        for (int j = 0; j < J; ++j) out[j] += w * d[j];
      }
  };
  for (int p = 0; p < N * N; ++p) {
    const float* e = &err[std::size_t(p) * J];
    add_around(B, p % N, p / N, kRadius, e, 1.0f, false);
    add_around(C, p % N, p / N, 2 * kRadius, e, 1.0f, true);
  }
  const auto energy = [&] {
    double s = 0;
    for (float v : B) s += double(v) * v;
    return s;
  };
  const double before = energy_ratio ? energy() : 0.0;
  const float sum_sq = float(kern.sum_sq);
  std::vector<float> d(std::size_t(J), 0.0f);
  const long proposals = long(o.rounds) * N * N;
  for (long it = 0; it < proposals; ++it) {
    const uint64_t r = draws.next();
    const int p = int((r & 0xffffffffu) * uint64_t(N * N) >> 32), q = int((r >> 32) * uint64_t(N * N) >> 32);
    if (p == q) continue;
    // The toroidal offset q - p, for the kernels' overlap.
    int dx = q % N - p % N, dy = q / N - p / N;
    dx = dx > N / 2 ? dx - N : dx < -N / 2 ? dx + N : dx;
    dy = dy > N / 2 ? dy - N : dy < -N / 2 ? dy + N : dy;
    const float overlap = std::abs(dx) <= 2 * kRadius && std::abs(dy) <= 2 * kRadius
                              ? float(kern.ww[dy + 2 * kRadius][dx + 2 * kRadius])
                              : 0.0f;
    const float *eq = &err[std::size_t(pick[std::size_t(q)]) * J], *ep = &err[std::size_t(pick[std::size_t(p)]) * J],
                *cp = &C[std::size_t(p) * J], *cq = &C[std::size_t(q) * J];
    const float self = 2 * sum_sq - 2 * overlap;
    float change = 0;
    for (int j = 0; j < J; ++j) {
      const float dj = eq[j] - ep[j];
      d[std::size_t(j)] = dj;
      change += dj * (2 * (cp[j] - cq[j]) + self * dj);
    }
    if (change >= 0) continue;  // greedy descent: the blurred energy only falls
    std::swap(pick[std::size_t(p)], pick[std::size_t(q)]);
    add_around(B, p % N, p / N, kRadius, d.data(), 1.0f, false);
    add_around(C, p % N, p / N, 2 * kRadius, d.data(), 1.0f, true);
    add_around(B, q % N, q / N, kRadius, d.data(), -1.0f, false);
    add_around(C, q % N, q / N, 2 * kRadius, d.data(), -1.0f, true);
  }
  if (energy_ratio) *energy_ratio = before > 0 ? energy() / before : 1.0;
  ScreenKeyTile t;
  t.size = N, t.spp = spp;
  t.keys.resize(pick.size());
  for (std::size_t p = 0; p < pick.size(); ++p) t.keys[p] = cand[std::size_t(pick[p])];
  return t;
}

namespace {

constexpr char kMagic[8] = {'P', 'D', 'R', 'T', 'S', 'K', 'T', '1'};

bool read_tile(const std::filesystem::path& file, int size, int spp, std::size_t tables, ScreenKeyTile* out) {
  const std::size_t n = std::size_t(size) * size;
  const auto body = read_checksummed_file(file, std::string_view(kMagic, sizeof kMagic), n * sizeof(ScreenKey));
  if (!body) return false;
  out->size = size, out->spp = spp;
  out->keys.resize(n);
  std::memcpy(out->keys.data(), body->data(), body->size());
  for (const ScreenKey& k : out->keys)
    if (k.table >= tables || k.swap > 1) return false;
  return true;
}

}  // namespace

const ScreenKeyTile& cached_screen_keys(const std::vector<const uint32_t*>& tables, int dim, int spp) {
  int level = 1;
  while (level * 2 <= std::min(spp, 64)) level *= 2;
  // The key: the tables' first 64 points (what any tile reads) and the options.
  const ScreenKeyOptions o;
  const uint64_t fields[4] = {uint64_t(o.size), uint64_t(o.integrands), uint64_t(o.rounds), o.seed};
  uint64_t h = fnv1a(std::string_view(reinterpret_cast<const char*>(fields), sizeof fields));
  for (const uint32_t* t : tables) h = fnv1a(std::string_view(reinterpret_cast<const char*>(t), 64 * 4 * dim), h);
  static std::mutex mutex;
  static std::map<std::tuple<uint64_t, int, int>, std::unique_ptr<ScreenKeyTile>> tiles;
  std::lock_guard lock(mutex);  // ranks' threads ask once per sampler
  auto& slot = tiles[{h, dim, level}];
  if (slot) return *slot;
  char name[80];
  std::snprintf(name, sizeof name, "screen-keys-v1-d%d-s%d-%016llx.bin", dim, level, (unsigned long long)h);
  const std::filesystem::path file = cache_dir() / name;
  slot = std::make_unique<ScreenKeyTile>();
  if (read_tile(file, o.size, level, tables.size(), slot.get())) return *slot;
  warn("pdrt: optimising poisson-bn's " + std::string(dim == 2 ? "2-D" : "1-D") + " screen-space keys for " +
       std::to_string(level) + " spp into " + file.string() + " (once)");
  *slot = optimize_screen_keys(tables, dim, level, o);
  try {
    write_checksummed_file(
        file, std::string_view(kMagic, sizeof kMagic),
        std::string_view(reinterpret_cast<const char*>(slot->keys.data()), slot->keys.size() * sizeof(ScreenKey)));
  } catch (const std::exception& e) {
    warn(std::string("pdrt: warning: cannot cache the screen-space keys (") + e.what() +
         "); using the ones optimised in memory, which the next run optimises again");
  }
  return *slot;
}

}  // namespace pdrt
