#pragma once
// The end of a render: the image of the crop and the counts of the samples. On one process,
// the film's conversion. Distributed (docs/distributed.md), every rank converts the pixels of
// its own tiles, which it alone rendered (its film holds them whole, whatever the others' tiles
// hold), into image values, 48 bytes a pixel, and they move straight into rank 0's image
// (ProcessGroup::move_spans); the ranks' counts are summed. Not the tiles' accumulators, 224
// bytes a pixel, into rank 0's film for rank 0 to convert alone: at 1080p that is 464 MB of
// pages to map at the end of the job, on the rank every other one waits for.
#include "renderer/image/image.h"
#include "renderer/render/process_group.h"
#include "renderer/render/render_films.h"
#include "renderer/render/render_region.h"
#include "renderer/render/render_statistics.h"
#include "renderer/render/tile_waves.h"

namespace pdrt {

struct GatheredImage {
  Image image;          // rank 0's; empty on the others
  SampleCounts counts;  // over every pixel, on every rank
};

// Collective when distributed. Adds the bytes this rank sent and the seconds it took to `mine`.
GatheredImage gather_image(const RenderFilms& films, const TileWaves& tiles, const RenderRegion& region,
                           float exposure_stops, const ProcessGroup& group, RankStats& mine);

}  // namespace pdrt
