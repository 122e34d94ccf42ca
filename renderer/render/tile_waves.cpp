#include "renderer/render/tile_waves.h"

#include <algorithm>
#include <cstddef>

namespace pdrt {

TileWaves::TileWaves(int width, int height, const PixelRect& region, int spread)
    : tx_((width + kTile - 1) / kTile), region_(region), spread_(spread) {
  const int ty = (height + kTile - 1) / kTile;
  const int period = spread > 0 ? 1 + (2 * spread + kTile - 1) / kTile : 1;
  waves_.resize(std::size_t(period) * period);
  for (int t = 0; t < tx_ * ty; ++t) {
    const int x0 = (t % tx_) * kTile, y0 = (t / tx_) * kTile;
    if (x0 + kTile <= region.x0 || x0 >= region.x1 || y0 + kTile <= region.y0 || y0 >= region.y1) continue;
    waves_[std::size_t((t / tx_) % period) * period + (t % tx_) % period].push_back(t);
  }
}

PixelRect TileWaves::pixels(int t) const {
  return PixelRect{std::max((t % tx_) * kTile, region_.x0), std::min((t % tx_) * kTile + kTile, region_.x1),
                   std::max((t / tx_) * kTile, region_.y0), std::min((t / tx_) * kTile + kTile, region_.y1)};
}

PixelRect TileWaves::footprint(int t) const {
  return PixelRect{
      std::max((t % tx_) * kTile - spread_, region_.x0), std::min((t % tx_) * kTile + kTile + spread_, region_.x1),
      std::max((t / tx_) * kTile - spread_, region_.y0), std::min((t / tx_) * kTile + kTile + spread_, region_.y1)};
}

std::vector<int> TileWaves::tiles_of(int rank, int ranks) const {
  std::vector<int> out;
  for (const std::vector<int>& wave : waves_)
    for (std::size_t j : rank_tiles(wave.size(), rank, ranks)) out.push_back(wave[j]);
  return out;
}

std::vector<std::size_t> rank_tiles(std::size_t wave_size, int rank, int ranks) {
  std::vector<std::size_t> tiles;
  for (std::size_t j = std::size_t(rank); j < wave_size; j += std::size_t(ranks)) tiles.push_back(j);
  return tiles;
}

}  // namespace pdrt
