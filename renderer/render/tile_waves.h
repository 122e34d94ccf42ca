#pragma once
// The 16x16 tiles of a render, in waves. Splatting writes into neighbouring tiles, so tiles
// run in waves whose footprints (tile plus the pixels its splats reach) are disjoint: no
// locks, and every pixel receives its contributions in the same order at any thread count
// (wave order, then the tile's pixel order). Tiles and waves are the full image's under a
// crop window too, so a pixel's contributions come in the same order as in the full render;
// only tiles that meet the rendered rectangle are in a wave.
#include "renderer/scene/crop_window.h"

#include <cstddef>
#include <vector>

namespace pdrt {

class TileWaves {
 public:
  static constexpr int kTile = 16;

  // Tiles of a width x height image that meet `region`; `spread`: pixels beyond a tile its
  // samples reach (the splat margin when splatting, else 0).
  TileWaves(int width, int height, const PixelRect& region, int spread);

  // Each wave's tiles (indices in row-major order over the image), waves in order.
  const std::vector<std::vector<int>>& waves() const { return waves_; }
  // Tile t's pixels within the region.
  PixelRect pixels(int t) const;
  // Tile t's footprint within the region: its pixels and the ones its samples reach.
  PixelRect footprint(int t) const;
  const PixelRect& region() const { return region_; }
  // The tile holding image pixel (x, y).
  int tile_at(int x, int y) const { return (y / kTile) * tx_ + x / kTile; }
  int spread() const { return spread_; }
  // The tiles `rank` of `ranks` renders (rank_tiles), wave by wave: the same list on every rank.
  std::vector<int> tiles_of(int rank, int ranks) const;

 private:
  int tx_;  // tiles per row
  PixelRect region_;
  int spread_;
  std::vector<std::vector<int>> waves_;
};

// Under mpirun tile j of each wave belongs to rank j mod `ranks`: `rank`'s positions in a wave
// of `wave_size` tiles. The assignment depends only on the image, so every rank knows every
// rank's tiles.
std::vector<std::size_t> rank_tiles(std::size_t wave_size, int rank, int ranks);

}  // namespace pdrt
