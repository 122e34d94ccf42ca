#include "renderer/render/wave_exchange.h"

#include <chrono>
#include <algorithm>
#include <cstdint>
#include <cstring>

namespace pdrt {

WaveExchange::WaveExchange(const ProcessGroup& group, const TileWaves& tiles, std::vector<Film*> films)
    : group_(group), tiles_(tiles), films_(std::move(films)) {}

namespace {
constexpr std::byte kInterrupted{1}, kListed{2};  // a block's flag bits
}  // namespace

bool WaveExchange::exchange(const std::vector<int>& wave, bool interrupted, RankStats& mine,
                            const std::vector<std::size_t>* changed) const {
  const int nranks = group_.size(), me = group_.rank();
  const auto e0 = std::chrono::steady_clock::now();
  std::vector<std::byte> out(1, interrupted ? kInterrupted : std::byte(0));
  pack(wave, changed, out);
  mine.bytes_sent += int64_t(out.size()) * (nranks - 1);
  std::vector<std::vector<std::byte>> in = group_.all_gather(out);
  bool any = false;
  for (int r = 0; r < nranks; ++r) {
    if ((in[std::size_t(r)][0] & kInterrupted) != std::byte(0)) any = true;
    if (r != me) unpack(wave, r, in[std::size_t(r)].data());
  }
  mine.exchange_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - e0).count();
  return any;
}

bool WaveExchange::exchange_to_lead(const std::vector<int>& wave, bool interrupted, RankStats& mine,
                                    const std::vector<std::size_t>* changed) const {
  const bool any = any_interrupted(interrupted, mine);
  const int me = group_.rank();
  const auto e0 = std::chrono::steady_clock::now();
  std::vector<std::byte> out(1, interrupted ? kInterrupted : std::byte(0));
  pack(wave, changed, out);
  if (me != 0) mine.bytes_sent += int64_t(out.size());
  const GatheredBytes in = group_.gather_to_lead(out);  // empty but on rank 0
  for (std::size_t r = 0; r < in.blocks(); ++r)
    if (int(r) != me) unpack(wave, int(r), in.block(r));
  mine.exchange_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - e0).count();
  return any;
}

bool WaveExchange::any_interrupted(bool interrupted, RankStats& mine) const {
  const auto e0 = std::chrono::steady_clock::now();
  bool any = false;
  for (const std::vector<std::byte>& b : group_.all_gather({std::byte(interrupted ? 1 : 0)}))
    any = any || b[0] != std::byte(0);
  mine.bytes_sent += group_.size() - 1;
  mine.exchange_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - e0).count();
  return any;
}

// copy(row, at, n): the film row of n bytes and its offset in the block, the footprints of
// `tiles` (positions in `wave`) from offset `at` on.
template <class Copy>
void WaveExchange::rows(const std::vector<int>& wave, const std::vector<std::size_t>& tiles, std::size_t at,
                        Copy&& copy) const {
  const PixelRect& region = tiles_.region();
  for (std::size_t j : tiles) {
    const PixelRect f = tiles_.footprint(wave[j]);
    for (Film* fm : films_) {
      if (!fm) continue;
      const std::size_t n = sizeof(PixelAccum) * std::size_t(f.width());
      for (int y = f.y0; y < f.y1; ++y, at += n) copy(&fm->at(f.x0 - region.x0, y - region.y0), at, n);
    }
  }
}

void WaveExchange::pack(const std::vector<int>& wave, const std::vector<std::size_t>* changed,
                        std::vector<std::byte>& bytes) const {
  const std::vector<std::size_t> all =
      changed ? std::vector<std::size_t>{} : rank_tiles(wave.size(), group_.rank(), group_.size());
  const std::vector<std::size_t>& tiles = changed ? *changed : all;
  std::size_t at = 1;
  if (changed) {
    bytes[0] |= kListed;
    at += sizeof(uint32_t) * (1 + tiles.size());
  }
  std::size_t end = at;
  rows(wave, tiles, at, [&](PixelAccum*, std::size_t a, std::size_t n) { end = a + n; });
  bytes.resize(std::max<std::size_t>(bytes.size(), end));  // sized once: hundreds of MB at 1080p
  if (changed) {
    const uint32_t count = uint32_t(tiles.size());
    std::memcpy(bytes.data() + 1, &count, sizeof count);
    for (std::size_t i = 0; i < tiles.size(); ++i) {
      const uint32_t j = uint32_t(tiles[i]);
      std::memcpy(bytes.data() + 1 + sizeof(uint32_t) * (1 + i), &j, sizeof j);
    }
  }
  rows(wave, tiles, at, [&](PixelAccum* row, std::size_t a, std::size_t n) { std::memcpy(bytes.data() + a, row, n); });
}

void WaveExchange::unpack(const std::vector<int>& wave, int rank, const std::byte* from) const {
  std::vector<std::size_t> tiles;
  std::size_t at = 1;
  if ((from[0] & kListed) != std::byte(0)) {
    uint32_t count = 0;
    std::memcpy(&count, from + 1, sizeof count);
    tiles.resize(count);
    for (uint32_t i = 0; i < count; ++i) {
      uint32_t j = 0;
      std::memcpy(&j, from + 1 + sizeof(uint32_t) * (1 + i), sizeof j);
      tiles[i] = j;
    }
    at += sizeof(uint32_t) * (1 + std::size_t(count));
  } else {
    tiles = rank_tiles(wave.size(), rank, group_.size());
  }
  rows(wave, tiles, at, [&](PixelAccum* row, std::size_t a, std::size_t n) { std::memcpy(row, from + a, n); });
}

}  // namespace pdrt
