// Pictures: the PNG encoding reads back to the same pixels, text and lines land
// where they should, and a plot draws its series.
#include "common/image/image.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <vector>

#include "common/image/line_plot.h"

namespace relmap::image {
namespace {

std::uint32_t ReadU32(const std::vector<unsigned char>& b, std::size_t at) {
  return (std::uint32_t{b[at]} << 24) | (std::uint32_t{b[at + 1]} << 16) |
         (std::uint32_t{b[at + 2]} << 8) | b[at + 3];
}

TEST(WritePng, EncodesThePixelsLosslessly) {
  Image image(7, 3, {10, 20, 30});
  image.Set(2, 1, {255, 0, 128});
  const std::string path = ::testing::TempDir() + "/relmap_image_test.png";
  ASSERT_TRUE(WritePng(image, path).ok());
  std::ifstream in(path, std::ios::binary);
  const std::vector<unsigned char> png((std::istreambuf_iterator<char>(in)), {});
  std::remove(path.c_str());

  ASSERT_GT(png.size(), 33u);
  EXPECT_EQ(png[1], 'P');
  EXPECT_EQ(ReadU32(png, 16), 7u);  // IHDR width
  EXPECT_EQ(ReadU32(png, 20), 3u);  // IHDR height
  const std::size_t idat = 33;      // signature 8 + IHDR chunk 25
  ASSERT_EQ(std::string(png.begin() + idat + 4, png.begin() + idat + 8), "IDAT");
  const std::uint32_t length = ReadU32(png, idat);
  std::vector<unsigned char> raw(std::size_t{3} * (7 * 3 + 1));
  uLongf raw_size = raw.size();
  ASSERT_EQ(uncompress(raw.data(), &raw_size, png.data() + idat + 8, length), Z_OK);
  ASSERT_EQ(raw_size, raw.size());
  // Row 1 starts at 22 (filter byte, then 7 RGB pixels per row); pixel 2 at +1+6.
  EXPECT_EQ(raw[22], 0);
  EXPECT_EQ(raw[22 + 1 + 6], 255);
  EXPECT_EQ(raw[22 + 1 + 8], 128);
  EXPECT_EQ(raw[1], 10);
}

TEST(WritePng, UnwritablePathIsAnError) {
  EXPECT_FALSE(WritePng(Image(2, 2), "/nonexistent/dir/x.png").ok());
}

TEST(Image, DrawsTextInTheFiveBySevenFont) {
  Image image(12, 7);
  image.Text(0, 0, "1", {0, 0, 0});
  // '1' = 00100 01100 00100 ...: pixel (2, 0) set, (0, 0) not, (1, 1) set.
  EXPECT_EQ(image.At(2, 0), (Rgb{0, 0, 0}));
  EXPECT_EQ(image.At(0, 0), (Rgb{255, 255, 255}));
  EXPECT_EQ(image.At(1, 1), (Rgb{0, 0, 0}));
  EXPECT_EQ(Image::TextWidth("ab", 2), 24);
}

TEST(Image, LinesClipAtTheBorder) {
  Image image(5, 5);
  image.Line(-10, 2, 20, 2, {1, 2, 3});
  for (int x = 0; x < 5; ++x) EXPECT_EQ(image.At(x, 2), (Rgb{1, 2, 3}));
  EXPECT_EQ(image.At(0, 1), (Rgb{255, 255, 255}));
}

TEST(RenderLinePlot, DrawsEverySeriesInItsColour) {
  Series a{"a", SeriesColour(0), {0, 1, 2}, {0, 1, 0}, {}, {}};
  Series b{"b", SeriesColour(1), {0, 1, 2}, {1, 0, 1}, {0.5, 0, 0.5}, {1, 0.5, 1}};
  const Image image = RenderLinePlot(PlotOptions{"t", "x", "y", 300, 200, {}, {}}, {a, b});
  int seen_a = 0, seen_b = 0;
  for (const Rgb& p : image.pixels()) {
    seen_a += p == SeriesColour(0) ? 1 : 0;
    seen_b += p == SeriesColour(1) ? 1 : 0;
  }
  EXPECT_GT(seen_a, 100);
  EXPECT_GT(seen_b, 100);
}

}  // namespace
}  // namespace relmap::image
