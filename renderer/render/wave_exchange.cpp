#include "renderer/render/wave_exchange.h"

#include <chrono>
#include <algorithm>
#include <cstdint>
#include <cstring>

namespace pdrt {

WaveExchange::WaveExchange(const ProcessGroup& group, const TileWaves& tiles, std::vector<Film*> films)
    : group_(group), tiles_(tiles), films_(std::move(films)) {}

namespace {
constexpr std::byte kInterrupted{1}, kListed{2};  // a header's flag bits
}  // namespace

bool WaveExchange::exchange(const std::vector<int>& wave, bool interrupted, RankStats& mine,
                            const std::vector<std::size_t>* changed) const {
  const int nranks = group_.size(), me = group_.rank();
  const auto e0 = std::chrono::steady_clock::now();
  const std::vector<std::byte> head = header(interrupted, changed);
  const std::vector<std::vector<std::byte>> heads = group_.all_gather(head);
  const std::vector<ByteSpan> out = spans(wave, tiles_in(wave, me, head.data()));
  std::vector<std::vector<ByteSpan>> send(nranks, out), recv(nranks);
  send[std::size_t(me)].clear();
  bool any = false;
  for (int r = 0; r < nranks; ++r) {
    if ((heads[std::size_t(r)][0] & kInterrupted) != std::byte(0)) any = true;
    if (r != me) recv[std::size_t(r)] = spans(wave, tiles_in(wave, r, heads[std::size_t(r)].data()));
  }
  group_.move_spans(send, recv);
  mine.bytes_sent += int64_t(head.size() + span_bytes(out)) * (nranks - 1);
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

std::vector<std::byte> WaveExchange::header(bool interrupted, const std::vector<std::size_t>* changed) {
  std::vector<std::byte> head(1, interrupted ? kInterrupted : std::byte(0));
  if (!changed) return head;
  head[0] |= kListed;
  const uint32_t count = uint32_t(changed->size());
  head.resize(1 + sizeof(uint32_t) * (1 + std::size_t(count)));
  std::memcpy(head.data() + 1, &count, sizeof count);
  for (uint32_t i = 0; i < count; ++i) {
    const uint32_t j = uint32_t((*changed)[i]);
    std::memcpy(head.data() + 1 + sizeof(uint32_t) * (1 + std::size_t(i)), &j, sizeof j);
  }
  return head;
}

std::vector<std::size_t> WaveExchange::tiles_in(const std::vector<int>& wave, int rank, const std::byte* head) const {
  if ((head[0] & kListed) == std::byte(0)) return rank_tiles(wave.size(), rank, group_.size());
  uint32_t count = 0;
  std::memcpy(&count, head + 1, sizeof count);
  std::vector<std::size_t> tiles(count);
  for (uint32_t i = 0; i < count; ++i) {
    uint32_t j = 0;
    std::memcpy(&j, head + 1 + sizeof(uint32_t) * (1 + std::size_t(i)), sizeof j);
    tiles[i] = j;
  }
  return tiles;
}

std::vector<ByteSpan> WaveExchange::spans(const std::vector<int>& wave, const std::vector<std::size_t>& tiles) const {
  std::vector<ByteSpan> out;
  const PixelRect& region = tiles_.region();
  for (std::size_t j : tiles) {
    const PixelRect f = tiles_.footprint(wave[j]);
    for (Film* fm : films_) {
      if (!fm) continue;
      const std::size_t n = sizeof(PixelAccum) * std::size_t(f.width());
      for (int y = f.y0; y < f.y1; ++y)
        out.push_back({reinterpret_cast<std::byte*>(&fm->at(f.x0 - region.x0, y - region.y0)), n});
    }
  }
  return out;
}

std::size_t WaveExchange::span_bytes(const std::vector<ByteSpan>& spans) {
  std::size_t n = 0;
  for (const ByteSpan& s : spans) n += s.size;
  return n;
}

}  // namespace pdrt
