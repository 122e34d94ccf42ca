#include "renderer/compare/demonstration_sheet.h"

#include "renderer/compare/heat_maps.h"
#include "renderer/compare/zoomed_crop.h"
#include "renderer/image/image_output.h"
#include "renderer/image/image_text.h"
#include "sampling/core/errors.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace pdrt {

namespace {

// Margins and bands of the sheet, in pixels.
constexpr int kPad = 8, kLabelWidth = 104, kTitleHeight = 24, kHeaderHeight = 20;
constexpr int kInnerGap = 2, kColumnGap = 10, kReferenceGap = 16, kRowGap = 6;
constexpr int kBarGap = 10, kBarLabelHeight = 18, kTickGap = 3, kTickHeight = 14;
constexpr int kTextSize = 13, kSmallTextSize = 11;
constexpr std::array<float, 3> kInk = {0, 0, 0};

struct Canvas {
  const DemoLayout& l;
  std::vector<float>& rgb;
  bool labelled = true;

  void set(int x, int y, const Vec3& c) {
    const std::size_t i = 3 * (std::size_t(y) * l.width + x);
    rgb[i] = c.x, rgb[i + 1] = c.y, rgb[i + 2] = c.z;
  }
  // `value(cx, cy)` of every crop pixel, replicated zoom x zoom at (x0, y0).
  template <class F>
  void paste(int x0, int y0, const F& value) {
    paste_zoomed(rgb, l.width, x0, y0, l.side / l.zoom, l.zoom, value);
  }
  // Text with its baseline's left end at (x, y); `centre` > 0 centres it in that width from x.
  void text(int x, int y, const std::string& s, int size = kTextSize, int centre = 0) {
    int w = text_width(s, size);
    if (w < 0) {
      labelled = false;
      return;
    }
    if (centre > 0 && w > centre && size > kSmallTextSize) w = text_width(s, size = kSmallTextSize);
    if (centre > 0) x += std::max(0, (centre - w) / 2);
    labelled = draw_text(rgb, l.width, l.height, x, y, size, kInk, s) && labelled;
  }
};

void check_input(const DemoInput& in) {
  const std::size_t cells = in.samplers.size() * in.spp.size();
  if (cells == 0 || in.images.size() != cells || in.errors.size() != cells || !in.reference)
    throw std::invalid_argument("demonstration_picture: one image and one error map per sampler and spp");
  const Image& ref = *in.reference;
  const auto [x, y, c] = in.window;
  if (c < 1 || x < 0 || y < 0 || x + c > ref.width || y + c > ref.height)
    throw std::invalid_argument("demonstration_picture: the window leaves the image");
  for (std::size_t i = 0; i < cells; ++i)
    if (!in.images[i] || !in.errors[i] || in.images[i]->width != ref.width || in.images[i]->height != ref.height ||
        in.errors[i]->size() != std::size_t(ref.width) * ref.height)
      throw std::invalid_argument("demonstration_picture: an image or error map of another size");
}

// The colour bar: the ramp from 0 to `scale`, its quantity above and three values below.
void draw_colour_bar(Canvas& cv, float scale) {
  const DemoLayout& l = cv.l;
  for (int x = 0; x < l.bar_width; ++x) {
    const Vec3 c = heat(float(x) / float(std::max(1, l.bar_width - 1)));
    for (int y = 0; y < kDemoBarHeight; ++y) cv.set(l.bar_x + x, l.bar_y + y, c);
  }
  cv.text(l.bar_x, l.bar_y - 5,
          "|luminance of (image - reference) blurred by a Gaussian, sigma = 1 px|; one scale for the sheet",
          kSmallTextSize);
  const int base = l.bar_y + kDemoBarHeight + kTickGap + kTickHeight - 3;
  for (int k = 0; k <= 2; ++k) {
    char v[32];
    std::snprintf(v, sizeof v, k == 0 ? "0" : "%.3g", double(scale) * k / 2);
    const int w = std::max(0, text_width(v, kSmallTextSize));
    const int x = l.bar_x + (l.bar_width - 1) * k / 2 - (k == 0 ? 0 : k == 1 ? w / 2 : w);
    cv.text(x, base, v, kSmallTextSize);
  }
}

}  // namespace

std::array<int, 2> DemoLayout::image_at(int row, int column) const {
  return {grid_x + column * cell_step, grid_y + row * row_step};
}

std::array<int, 2> DemoLayout::heat_at(int row, int column) const {
  return {grid_x + column * cell_step + side + kInnerGap, grid_y + row * row_step};
}

DemoLayout demonstration_layout(int samplers, int spps, int crop_side) {
  if (samplers < 1 || spps < 1 || crop_side < 1) throw std::invalid_argument("demonstration_layout: empty sheet");
  DemoLayout l;
  l.zoom = std::max(1, kDemoCellSide / crop_side);
  l.side = crop_side * l.zoom;
  l.grid_x = kPad + kLabelWidth, l.grid_y = kPad + kTitleHeight + kHeaderHeight;
  l.cell_step = 2 * l.side + kInnerGap + kColumnGap, l.row_step = l.side + kRowGap;
  const int cells_width = spps * l.cell_step - kColumnGap;
  l.reference_x = l.grid_x + cells_width + kReferenceGap;
  l.width = l.reference_x + l.side + kPad;
  l.bar_x = l.grid_x, l.bar_width = std::min(cells_width, 360);
  l.bar_y = l.grid_y + samplers * l.row_step - kRowGap + kBarGap + kBarLabelHeight;
  l.height = l.bar_y + kDemoBarHeight + kTickGap + kTickHeight + kPad;
  return l;
}

DemoPicture demonstration_picture(const DemoInput& in) {
  check_input(in);
  const int rows = int(in.samplers.size()), cols = int(in.spp.size());
  // Plain ints, not structured bindings: the lambdas below capture them (clang before 16
  // refuses to capture a structured binding).
  const int wx = in.window[0], wy = in.window[1], c = in.window[2];
  const int W = in.reference->width;
  DemoPicture pic;
  pic.layout = demonstration_layout(rows, cols, c);
  const DemoLayout& l = pic.layout;
  std::vector<float> crop_errors;
  for (const auto* e : in.errors)
    for (int y = 0; y < c; ++y)
      for (int x = 0; x < c; ++x) crop_errors.push_back((*e)[std::size_t(wy + y) * W + wx + x]);
  pic.scale = heat_scale(std::move(crop_errors));
  pic.rgb.assign(std::size_t(3) * l.width * l.height, 1.0f);
  Canvas cv{l, pic.rgb};
  auto image_crop = [&](const Image& im) {
    return [&im, wx, wy](int x, int y) { return srgb_pixel(im, wx + x, wy + y); };
  };
  for (int r = 0; r < rows; ++r)
    for (int k = 0; k < cols; ++k) {
      const std::size_t i = std::size_t(r) * cols + k;
      const auto [ix, iy] = l.image_at(r, k);
      cv.paste(ix, iy, image_crop(*in.images[i]));
      const auto [hx, hy] = l.heat_at(r, k);
      const std::vector<float>& e = *in.errors[i];
      cv.paste(hx, hy, [&](int x, int y) { return heat(e[std::size_t(wy + y) * W + wx + x] / pic.scale); });
    }
  cv.paste(l.reference_x, l.grid_y, image_crop(*in.reference));
  // The labels: title, columns, rows, then the colour bar.
  cv.text(kPad, kPad + kTitleHeight - 8, in.title);
  const int header = l.grid_y - 6;
  for (int k = 0; k < cols; ++k)
    cv.text(l.image_at(0, k)[0], header, std::to_string(in.spp[std::size_t(k)]) + " spp: image | blurred error",
            kTextSize, 2 * l.side + kInnerGap);
  cv.text(l.reference_x, header, "reference", kTextSize, l.side);
  for (int r = 0; r < rows; ++r)
    cv.text(kPad, l.image_at(r, 0)[1] + l.side / 2 + 5, in.samplers[std::size_t(r)], kTextSize);
  draw_colour_bar(cv, pic.scale);
  pic.labelled = cv.labelled;
  return pic;
}

void validate_demo_crop(const CompareOptions& o, int width, int height) {
  if (!o.demo_crop) return;
  const auto [x, y, c] = *o.demo_crop;
  const std::string given =
      "--demo-crop " + std::to_string(x) + "," + std::to_string(y) + "," + std::to_string(c) + ": ";
  if (!demonstration_drawn(o))
    throw UsageError(given + "the demonstration sheet is drawn for at most " + std::to_string(kDemoMaxSamplers) +
                     " samplers and " + std::to_string(kDemoMaxSpp) + " sample counts, got " +
                     std::to_string(o.samplers.size()) + " and " + std::to_string(o.spp.size()));
  if (c < 1) throw UsageError(given + "the side must be >= 1");
  if (x < 0 || y < 0 || x + c > width || y + c > height)
    throw UsageError(given + "the square leaves the " + std::to_string(width) + "x" + std::to_string(height) +
                     " image (x + side <= " + std::to_string(width) + ", y + side <= " + std::to_string(height) + ")");
}

bool demonstration_drawn(const CompareOptions& o) {
  return !o.samplers.empty() && !o.spp.empty() && int(o.samplers.size()) <= kDemoMaxSamplers &&
         int(o.spp.size()) <= kDemoMaxSpp;
}

void write_demonstration_sheet(const ReportContext& ctx, CompareResults& results) {
  if (!demonstration_drawn(ctx.o)) return;
  DemonstrationSheet& d = results.demonstration;
  d.window_given = ctx.o.demo_crop.has_value();
  d.window = d.window_given ? *ctx.o.demo_crop : results.crops.window;
  DemoInput in;
  in.title = std::filesystem::path(ctx.o.scene_label).filename().string() + ": seed 0's crop and its blurred error";
  in.samplers = ctx.o.samplers, in.spp = ctx.o.spp;
  for (const auto& name : ctx.o.samplers)
    for (int n : ctx.o.spp)
      for (const UniformRun& r : results.runs)
        if (r.sampler == name && r.spp == n) in.images.push_back(&r.image), in.errors.push_back(&r.blurred_error);
  in.reference = &results.reference.image;
  in.window = d.window;
  DemoPicture pic;
  try {
    pic = demonstration_picture(in);
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("demonstration sheet: ") + e.what());
  }
  d.drawn = true, d.file = "images/demonstration.png";
  d.zoom = pic.layout.zoom, d.width = pic.layout.width, d.height = pic.layout.height;
  d.scale = pic.scale, d.labelled = pic.labelled;
  write_display_png(ctx.o.out / d.file, d.width, d.height, pic.rgb);
  if (!pic.labelled) ctx.say("no font for the demonstration sheet's labels (DejaVu Sans): written without them");
}

}  // namespace pdrt
