// An 8-bit RGB raster with the few drawing operations relmap's pictures need
// (maps, segmentations, learning curves), and its PNG encoding.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "common/status.h"

namespace relmap::image {

using Rgb = std::array<std::uint8_t, 3>;

class Image {
 public:
  Image(int width, int height, Rgb background = {255, 255, 255});

  int width() const { return width_; }
  int height() const { return height_; }
  const std::vector<Rgb>& pixels() const { return pixels_; }

  // Drawing clips at the borders: coordinates outside the image are ignored.
  void Set(int x, int y, Rgb colour);
  Rgb At(int x, int y) const { return pixels_[static_cast<std::size_t>(y) * width_ + x]; }
  void FillRect(int x0, int y0, int x1, int y1, Rgb colour);  // inclusive corners
  // A straight line of the given thickness in pixels (Bresenham, square pen).
  void Line(int x0, int y0, int x1, int y1, Rgb colour, int thickness = 1);
  // Text in a 5×7 pixel font scaled by `scale`; (x, y) is the top-left corner.
  // Lower-case letters are drawn as capitals; unknown characters as a box.
  void Text(int x, int y, std::string_view text, Rgb colour, int scale = 1);
  static int TextWidth(std::string_view text, int scale = 1) {
    return static_cast<int>(text.size()) * 6 * scale;
  }

 private:
  int width_;
  int height_;
  std::vector<Rgb> pixels_;
};

// Writes `image` as an 8-bit RGB PNG (zlib-compressed, no filtering).
Status WritePng(const Image& image, const std::string& path);

}  // namespace relmap::image
