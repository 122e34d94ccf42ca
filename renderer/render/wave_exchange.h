#pragma once
// The exchange after each wave of a distributed render (docs/distributed.md): tile j of each
// wave belongs to rank j mod N. After the wave every rank sends the pixel state of its tiles'
// footprints (the tile, plus the splat margin when splatting) and copies the others' into its
// films. Footprints within a wave are disjoint and each was computed by one rank exactly as
// one process computes it, so every rank holds the single-process films, bit for bit, before
// the next wave.
#include "renderer/render/film.h"
#include "renderer/render/process_group.h"
#include "renderer/render/renderer.h"
#include "renderer/render/tile_waves.h"

#include <cstddef>
#include <vector>

namespace pdrt {

class WaveExchange {
 public:
  // `films`: the film, and the decision film or nullptr (the same on every rank).
  WaveExchange(const ProcessGroup& group, const TileWaves& tiles, std::vector<Film*> films);

  // Collective: every rank takes part in every exchange, interrupted or not, so none waits
  // forever. Sends this rank's footprints of `wave` with whether it was `interrupted`, copies
  // the others'; true when any rank was. Adds the bytes sent and the time taken to `mine`.
  // `changed`: when every rank held the same films before the wave, the positions j in `wave`
  // of this rank's tiles that took samples in it; only those are sent (the others' footprints
  // are the same everywhere), with their list. Null: every tile of this rank's is sent.
  bool exchange(const std::vector<int>& wave, bool interrupted, RankStats& mine,
                const std::vector<std::size_t>* changed = nullptr) const;
  // Collective: whether any rank was `interrupted`, without the blocks (a pass whose tiles no
  // other rank reads before the next pass: progressive_passes.h).
  bool any_interrupted(bool interrupted, RankStats& mine) const;

 private:
  // A rank's header: a flag byte (bit 0: the rank was interrupted; bit 1: a list follows),
  // then, with the list, its length and the positions j in the wave of the tiles it sends
  // (uint32 each). Without the list the rank sends every tile of its own. The footprints
  // themselves travel row by row from film to film (ProcessGroup::move_spans): no buffer of
  // the film's size is packed, sent or unpacked.
  static std::vector<std::byte> header(bool interrupted, const std::vector<std::size_t>* changed);
  // The positions in `wave` of the tiles `rank` sends, from its header.
  std::vector<std::size_t> tiles_in(const std::vector<int>& wave, int rank, const std::byte* head) const;
  // The films' rows of those tiles' footprints, tile by tile, in the same order on every rank.
  std::vector<ByteSpan> spans(const std::vector<int>& wave, const std::vector<std::size_t>& tiles) const;
  static std::size_t span_bytes(const std::vector<ByteSpan>& spans);

  const ProcessGroup& group_;
  const TileWaves& tiles_;
  std::vector<Film*> films_;
};

}  // namespace pdrt
