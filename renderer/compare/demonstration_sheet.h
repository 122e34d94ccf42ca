#pragma once
// The demonstration sheet of `pdrt compare` (issue 31 item 5): one row per sampler and one
// column per spp, each cell the seed-0 image's crop (left) beside the crop of its blurred-error
// heat map (right; blurred_heat_maps.h), all heat crops on one scale shared by the whole sheet
// (the 99th percentile of the cells' blurred errors) so that the error's fall with spp shows;
// then the reference's crop, labelled rows, columns and a labelled colour bar. The square is the
// detail window (detail_crops.h) or the one --demo-crop names; crops are zoomed by pixel
// replication to about kDemoCellSide pixels.
#include "renderer/compare/compare_results.h"
#include "renderer/compare/report_context.h"

#include <array>
#include <string>
#include <vector>

namespace pdrt {

// The sheet is drawn by default up to this many samplers and sample counts (a larger sheet is
// too wide to read); --demo-crop beyond them is refused.
inline constexpr int kDemoMaxSamplers = 8, kDemoMaxSpp = 6;
inline constexpr int kDemoCellSide = 96, kDemoBarHeight = 12;

// Where everything sits on a sheet of `samplers` rows and `spps` columns of crops `crop_side`
// pixels square. Pixel sizes are fixed (not measured from a font), so the sheet's size is too.
struct DemoLayout {
  int zoom = 1, side = 0;  // a crop pixel is zoom x zoom sheet pixels; a crop is side x side
  int width = 0, height = 0;
  int grid_x = 0, grid_y = 0;                              // the first cell's top left
  int cell_step = 0, row_step = 0;                         // from one column / row of cells to the next
  int reference_x = 0;                                     // the reference column's left (its crop in the first row)
  int bar_x = 0, bar_y = 0, bar_width = 0;                 // the colour bar, kDemoBarHeight high
  std::array<int, 2> image_at(int row, int column) const;  // a cell's image crop, top left
  std::array<int, 2> heat_at(int row, int column) const;   // a cell's heat crop, top left
};
DemoLayout demonstration_layout(int samplers, int spps, int crop_side);

struct DemoInput {
  std::string title;
  std::vector<std::string> samplers;              // rows
  std::vector<int> spp;                           // columns
  std::vector<const Image*> images;               // samplers x spp, row by row: seed 0's renders
  std::vector<const std::vector<float>*> errors;  // the same runs' blurred errors (W x H)
  const Image* reference = nullptr;
  std::array<int, 3> window{};  // x, y, side inside the images
};

struct DemoPicture {
  DemoLayout layout;
  float scale = 0;         // the heat ramp's top
  bool labelled = false;   // the labels were drawn (a font was found)
  std::vector<float> rgb;  // layout.width x layout.height display RGB
};
// std::invalid_argument when the window leaves the images or the inputs do not match.
DemoPicture demonstration_picture(const DemoInput& in);

// UsageError unless o.demo_crop (when set) is a square of side >= 1 inside a width x height
// image and the sheet is drawn; checked before rendering.
void validate_demo_crop(const CompareOptions& o, int width, int height);

// Whether the compare draws the sheet: at most kDemoMaxSamplers x kDemoMaxSpp.
bool demonstration_drawn(const CompareOptions& o);

// Writes images/demonstration.png and fills results.demonstration when demonstration_drawn.
// Needs results.runs' images and blurred errors, results.reference and results.crops.
void write_demonstration_sheet(const ReportContext& ctx, CompareResults& results);

}  // namespace pdrt
