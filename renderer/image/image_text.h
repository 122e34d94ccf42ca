#pragma once
// Labels drawn into the report's display-RGB sheets through the image module (OpenImageIO's
// FreeType text). The font is DejaVu Sans where the system has it (matplotlib, which the
// report's plots need, brings it), else OpenImageIO's default; with neither, nothing is drawn.
#include <array>
#include <string>
#include <vector>

namespace pdrt {

// The width in pixels of one line of `text` at `size` pixels, or -1 when no font is found.
int text_width(const std::string& text, int size);

// Draws one line of `text` into `rgb` (width x height display RGB) with the left end of its
// baseline at (x, y); false when no font is found (the image is then unchanged).
bool draw_text(std::vector<float>& rgb, int width, int height, int x, int y, int size,
               const std::array<float, 3>& colour, const std::string& text);

}  // namespace pdrt
