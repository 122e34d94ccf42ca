#include "renderer/render/wave_exchange.h"

#include <chrono>
#include <algorithm>
#include <cstring>

namespace pdrt {

WaveExchange::WaveExchange(const ProcessGroup& group, const TileWaves& tiles, std::vector<Film*> films)
    : group_(group), tiles_(tiles), films_(std::move(films)) {}

bool WaveExchange::exchange(const std::vector<int>& wave, bool interrupted, RankStats& mine) const {
  const int nranks = group_.size(), me = group_.rank();
  const auto e0 = std::chrono::steady_clock::now();
  std::vector<std::byte> out(1, std::byte(interrupted ? 1 : 0));
  pack(wave, me, out);
  mine.bytes_sent += int64_t(out.size()) * (nranks - 1);
  std::vector<std::vector<std::byte>> in = group_.all_gather(out);
  bool any = false;
  for (int r = 0; r < nranks; ++r) {
    if (in[std::size_t(r)][0] != std::byte(0)) any = true;
    if (r != me) unpack(wave, r, in[std::size_t(r)].data());
  }
  mine.exchange_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - e0).count();
  return any;
}

bool WaveExchange::exchange_to_lead(const std::vector<int>& wave, bool interrupted, RankStats& mine) const {
  const bool any = any_interrupted(interrupted, mine);
  const int me = group_.rank();
  const auto e0 = std::chrono::steady_clock::now();
  std::vector<std::byte> out(1, std::byte(interrupted ? 1 : 0));
  pack(wave, me, out);
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

// copy(row, at, n): the film row of n bytes and its offset in the block.
template <class Copy>
void WaveExchange::rows(const std::vector<int>& wave, int rank, Copy&& copy) const {
  const PixelRect& region = tiles_.region();
  std::size_t at = 1;  // byte 0: the rank was interrupted
  for (std::size_t j = std::size_t(rank); j < wave.size(); j += std::size_t(group_.size())) {
    const PixelRect f = tiles_.footprint(wave[j]);
    for (Film* fm : films_) {
      if (!fm) continue;
      const std::size_t n = sizeof(PixelAccum) * std::size_t(f.width());
      for (int y = f.y0; y < f.y1; ++y, at += n) copy(&fm->at(f.x0 - region.x0, y - region.y0), at, n);
    }
  }
}

void WaveExchange::pack(const std::vector<int>& wave, int rank, std::vector<std::byte>& bytes) const {
  std::size_t end = 1;
  rows(wave, rank, [&](PixelAccum*, std::size_t at, std::size_t n) { end = at + n; });
  bytes.resize(std::max<std::size_t>(bytes.size(), end));  // sized once: hundreds of MB at 1080p
  rows(wave, rank, [&](PixelAccum* row, std::size_t at, std::size_t n) { std::memcpy(bytes.data() + at, row, n); });
}

void WaveExchange::unpack(const std::vector<int>& wave, int rank, const std::byte* from) const {
  rows(wave, rank, [&](PixelAccum* row, std::size_t at, std::size_t n) { std::memcpy(row, from + at, n); });
}

}  // namespace pdrt
