#include "renderer/image/image_text.h"

#include "renderer/image/image_module.h"

namespace pdrt {

namespace {

// Fills `t`'s font with the first that works, remembered for the process; false without one.
bool with_font(PdrtImageText& t) {
  static const char* const kFonts[] = {"DejaVuSans", ""};
  static int chosen = -1;  // the report draws from one thread
  char error[256];
  for (int i = chosen < 0 ? 0 : chosen; i < 2; ++i) {
    t.font = kFonts[i];
    if (image_module().draw_text(&t, error, sizeof error) == 0) return chosen = i, true;
  }
  return false;
}

}  // namespace

int text_width(const std::string& text, int size) {
  PdrtImageText t{};
  t.size = size, t.text = text.c_str();
  return with_font(t) ? t.advance : -1;
}

bool draw_text(std::vector<float>& rgb, int width, int height, int x, int y, int size,
               const std::array<float, 3>& colour, const std::string& text) {
  if (rgb.size() != std::size_t(3) * width * height || text.empty()) return false;
  PdrtImageText t{};
  t.pixels = rgb.data(), t.width = width, t.height = height, t.x = x, t.y = y, t.size = size;
  for (int c = 0; c < 3; ++c) t.rgb[c] = colour[std::size_t(c)];
  t.text = text.c_str();
  return with_font(t);
}

}  // namespace pdrt
