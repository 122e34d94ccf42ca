#pragma once
// Per-pixel keys that distribute the error of neighbouring pixels as blue noise (Heitz,
// Belcour, Ostromoukhov, Coeurjolly & Iehl, "A Low-Discrepancy Sampler that Distributes Monte
// Carlo Errors as a Blue Noise in Screen Space", 2019): a toroidal tile of keys, one per pixel,
// each picking a table, an axis swap and a digital shift of that table's first `spp` points,
// chosen so that on an ensemble of step integrands the error image of the tile, blurred by a
// Gaussian of sigma 1 px, has the least energy: neighbours get complementary errors. The
// sampler composes every key with a digital shift uniform per (seed, family, bounce), so each
// value stays uniform (unbiased) and the tile's relations between pixels survive (the training
// integrands are drawn under such shifts too).
#include <cstdint>
#include <vector>

namespace pdrt {

struct ScreenKey {
  uint32_t x[2];   // digital shift per output axis
  uint16_t table;  // index into the tables the tile was optimised with
  uint16_t swap;   // 1: output axis k reads the table's axis 1 - k (2-D only)
};

struct ScreenKeyTile {
  int size = 0;  // size x size pixels, toroidal
  int spp = 0;   // the prefix the keys were optimised for
  std::vector<ScreenKey> keys;
  const ScreenKey& at(int x, int y) const {  // any pixel; the tile wraps
    const int m = size;
    return keys[std::size_t(((y % m) + m) % m) * std::size_t(m) + std::size_t(((x % m) + m) % m)];
  }
};

struct ScreenKeyOptions {
  int size = 64;
  int integrands = 1024;  // training step integrands (half-planes in 2-D, steps in 1-D)
  int rounds = 256;       // proposed swaps per pixel
  uint64_t seed = 0x736372656e6b6579ull;
};

// Optimises a tile for tables `tables` (each holding at least `spp` points of `dim` coordinates
// in 32-bit fixed point, 1 <= dim <= 2): deterministic for its inputs. `energy_ratio`, when
// given, receives the blurred error energy after / before on the training integrands.
ScreenKeyTile optimize_screen_keys(const std::vector<const uint32_t*>& tables, int dim, int spp,
                                   const ScreenKeyOptions& options = {}, double* energy_ratio = nullptr);

// The error of `spp` points of key k on a step integrand: exposed for tests and the bench.
// A half-plane {n . u > c} through a uniform point (2-D) or a step {u < c} (1-D), under a
// uniform digital shift g of the points.
struct StepIntegrand {
  double n[2], c, integral;
  uint32_t g[2];
};
StepIntegrand random_step(int dim, uint64_t key);
double key_error(const uint32_t* table, int dim, int spp, const ScreenKey& k, const StepIntegrand& f);

// The tile for `spp` (rounded down to a power of two, at most 64) of the given tables, from the
// cache directory (keyed by the tables' contents) or optimised and cached there.
const ScreenKeyTile& cached_screen_keys(const std::vector<const uint32_t*>& tables, int dim, int spp);

}  // namespace pdrt
