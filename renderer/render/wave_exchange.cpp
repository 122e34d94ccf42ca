#include "renderer/render/wave_exchange.h"

#include <chrono>
#include <cstring>

namespace pdrt {

WaveExchange::WaveExchange(const ProcessGroup& group, const TileWaves& tiles, std::vector<Film*> films)
    : group_(group), tiles_(tiles), films_(std::move(films)) {}

bool WaveExchange::exchange(const std::vector<int>& wave, bool interrupted, RankStats& mine) const {
  const int nranks = group_.size(), me = group_.rank();
  const auto e0 = std::chrono::steady_clock::now();
  std::vector<std::byte> out(1, std::byte(interrupted ? 1 : 0));
  blocks(wave, me, out, true);
  mine.bytes_sent += int64_t(out.size()) * (nranks - 1);
  std::vector<std::vector<std::byte>> in = group_.all_gather(out);
  bool any = false;
  for (int r = 0; r < nranks; ++r) {
    if (in[std::size_t(r)][0] != std::byte(0)) any = true;
    if (r != me) blocks(wave, r, in[std::size_t(r)], false);
  }
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

void WaveExchange::blocks(const std::vector<int>& wave, int rank, std::vector<std::byte>& bytes, bool pack) const {
  const PixelRect& region = tiles_.region();
  std::size_t at = 1;  // bytes[0]: the rank was interrupted
  for (std::size_t j = std::size_t(rank); j < wave.size(); j += std::size_t(group_.size())) {
    const PixelRect f = tiles_.footprint(wave[j]);
    for (Film* fm : films_) {
      if (!fm) continue;
      for (int y = f.y0; y < f.y1; ++y) {
        const std::size_t n = sizeof(PixelAccum) * std::size_t(f.width());
        PixelAccum* row = &fm->at(f.x0 - region.x0, y - region.y0);
        if (pack)
          bytes.resize(at + n), std::memcpy(bytes.data() + at, row, n);
        else
          std::memcpy(row, bytes.data() + at, n);
        at += n;
      }
    }
  }
}

}  // namespace pdrt
