#include "renderer/render/image_gather.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <chrono>
#include <cmath>
#include <cstring>

namespace pdrt {

namespace {

// A run of image pixels in one row of the crop, in crop coordinates.
struct Segment {
  int x0, x1, y;
  int width() const { return x1 - x0; }
};

// The crop's pixels of `rank`'s tiles, tile by tile in wave order, rows top to bottom: the
// same list on every rank.
std::vector<Segment> segments_of(const TileWaves& tiles, const PixelRect& crop, int rank, int ranks) {
  std::vector<Segment> out;
  for (int t : tiles.tiles_of(rank, ranks)) {
    const PixelRect p = tiles.pixels(t);
    const int x0 = std::max(p.x0, crop.x0), x1 = std::min(p.x1, crop.x1);
    if (x0 >= x1) continue;
    for (int y = std::max(p.y0, crop.y0); y < std::min(p.y1, crop.y1); ++y)
      out.push_back({x0 - crop.x0, x1 - crop.x0, y - crop.y0});
  }
  return out;
}

// Each plane of an image with its floats per pixel, in the order the planes travel.
std::vector<std::pair<std::vector<float>*, int>> planes(Image& img) {
  return {{&img.rgb, 3}, {&img.albedo, 3}, {&img.normal, 3}, {&img.samples, 1}, {&img.variance, 1}, {&img.depth, 1}};
}

}  // namespace

GatheredImage gather_image(const RenderFilms& films, const TileWaves& tiles, const RenderRegion& region,
                           float exposure_stops, const ProcessGroup& group, RankStats& mine) {
  GatheredImage out;
  const PixelRect& crop = region.crop;
  if (group.size() == 1) {
    out.image = films.image.image(exposure_stops, region.crop_x0(), region.crop_y0(), crop.width(), crop.height());
    out.counts = count_pixels(films, region, region.rect);
    return out;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const int me = group.rank(), nranks = group.size();

  // The counts of this rank's tiles (together they cover the rendered rectangle once), summed.
  const std::vector<int> mine_tiles = tiles.tiles_of(me, nranks);
  const SampleCounts counted = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, mine_tiles.size()), SampleCounts{},
      [&](const tbb::blocked_range<std::size_t>& r, SampleCounts c) {
        for (std::size_t k = r.begin(); k != r.end(); ++k)
          c += count_pixels(films, region, tiles.pixels(mine_tiles[k]));
        return c;
      },
      [](SampleCounts a, const SampleCounts& b) { return a += b; });
  std::vector<std::byte> bytes(sizeof counted);
  std::memcpy(bytes.data(), &counted, sizeof counted);
  for (const std::vector<std::byte>& b : group.all_gather(bytes)) {
    SampleCounts c;
    std::memcpy(&c, b.data(), sizeof c);
    out.counts += c;
  }
  mine.bytes_sent += int64_t(sizeof counted) * (nranks - 1);

  // This rank's pixels of the crop, converted into `into` at `place(k, s)` for segment k.
  const float scale = std::exp2(exposure_stops);
  const std::vector<Segment> own = segments_of(tiles, crop, me, nranks);
  const auto convert = [&](Image& into, const auto& place) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, own.size()), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t k = r.begin(); k != r.end(); ++k) {
        const Segment& s = own[k];
        const std::size_t at = place(k, s);
        for (int x = s.x0; x < s.x1; ++x)
          write_image_pixel(films.image.at(region.crop_x0() + x, region.crop_y0() + s.y), scale, into,
                            at + std::size_t(x - s.x0));
      }
    });
  };
  std::vector<std::vector<ByteSpan>> send(static_cast<std::size_t>(nranks)), recv(static_cast<std::size_t>(nranks));
  Image strip;  // a rank's pixels one after the other, segment by segment: one row
  if (me == 0) {
    out.image = sized_image(crop.width(), crop.height());
    convert(out.image, [&](std::size_t, const Segment& s) { return std::size_t(s.y) * crop.width() + s.x0; });
    for (int r = 1; r < nranks; ++r) {
      const std::vector<Segment> theirs = segments_of(tiles, crop, r, nranks);
      for (auto [plane, comps] : planes(out.image))
        for (const Segment& s : theirs)
          recv[std::size_t(r)].push_back(
              {reinterpret_cast<std::byte*>(plane->data() + (std::size_t(s.y) * crop.width() + s.x0) * comps),
               std::size_t(s.width()) * std::size_t(comps) * sizeof(float)});
    }
  } else {
    std::vector<std::size_t> start(own.size() + 1, 0);
    for (std::size_t k = 0; k < own.size(); ++k) start[k + 1] = start[k] + std::size_t(own[k].width());
    strip = sized_image(int(start.back()), 1);
    convert(strip, [&](std::size_t k, const Segment&) { return start[k]; });
    for (auto [plane, comps] : planes(strip)) {
      if (plane->empty()) continue;  // no pixel of the crop
      send[0].push_back({reinterpret_cast<std::byte*>(plane->data()), plane->size() * sizeof(float)});
      mine.bytes_sent += int64_t(plane->size() * sizeof(float));
    }
  }
  group.move_spans(send, recv);
  mine.exchange_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace pdrt
