// Drawing on the RGB raster.
#include "common/image/image.h"

#include <algorithm>
#include <cstdlib>

#include "common/image/font5x7.h"

namespace relmap::image {

Image::Image(int width, int height, Rgb background)
    : width_(width),
      height_(height),
      pixels_(static_cast<std::size_t>(width) * height, background) {}

void Image::Set(int x, int y, Rgb colour) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
  pixels_[static_cast<std::size_t>(y) * width_ + x] = colour;
}

void Image::FillRect(int x0, int y0, int x1, int y1, Rgb colour) {
  for (int y = std::max(0, std::min(y0, y1)); y <= std::min(height_ - 1, std::max(y0, y1)); ++y) {
    for (int x = std::max(0, std::min(x0, x1)); x <= std::min(width_ - 1, std::max(x0, x1)); ++x) {
      pixels_[static_cast<std::size_t>(y) * width_ + x] = colour;
    }
  }
}

void Image::Line(int x0, int y0, int x1, int y1, Rgb colour, int thickness) {
  const int dx = std::abs(x1 - x0);
  const int dy = -std::abs(y1 - y0);
  const int sx = x0 < x1 ? 1 : -1;
  const int sy = y0 < y1 ? 1 : -1;
  const int low = -(thickness - 1) / 2;
  const int high = thickness / 2;
  for (int error = dx + dy;;) {
    FillRect(x0 + low, y0 + low, x0 + high, y0 + high, colour);
    if (x0 == x1 && y0 == y1) return;
    const int twice = 2 * error;
    if (twice >= dy) error += dy, x0 += sx;
    if (twice <= dx) error += dx, y0 += sy;
  }
}

void Image::Text(int x, int y, std::string_view text, Rgb colour, int scale) {
  for (char c : text) {
    const Glyph& glyph = GlyphOf(c);
    for (int row = 0; row < 7; ++row) {
      for (int column = 0; column < 5; ++column) {
        if ((glyph[row] >> (4 - column)) & 1) {
          FillRect(x + column * scale, y + row * scale, x + (column + 1) * scale - 1,
                   y + (row + 1) * scale - 1, colour);
        }
      }
    }
    x += 6 * scale;
  }
}

}  // namespace relmap::image
