// The PCD reader of common/pcd: the LZF codec on hand-made streams, the header parser's
// answer for a header that has not fully arrived, and a file read back as written. The
// server's decoder over it is tested on the real Kinect files in tests/perception.
#include "common/pcd/pcd_reader.h"

#include <gtest/gtest.h>

#include <string>

#include "common/pcd/lzf.h"
#include "common/pcd/pcd_encoder.h"
#include "common/pcd/pcd_header.h"

namespace relmap::pcd {
namespace {

std::string Bytes(std::initializer_list<int> values) {
  std::string bytes;
  for (const int v : values) bytes.push_back(static_cast<char>(v));
  return bytes;
}

TEST(LzfDecompress, ALiteralRunThenAnOverlappingBackReference) {
  // Control 2: the 3 literals "abc". Control 96 = (5 - 2) << 5 with distance byte 2:
  // 5 bytes copied from 3 behind, overlapping what they produce: "abcab".
  const std::string in = Bytes({2, 'a', 'b', 'c', 96, 2});
  std::string out(8, '\0');
  ASSERT_EQ(LzfDecompress(in, out.data(), out.size()), 8u);
  EXPECT_EQ(out, "abcabcab");
}

TEST(LzfDecompress, ALongReferenceTakesAnExtraLengthByte) {
  // Control 224 = 7 << 5: length 7 + 3 (extra byte) + 2 = 12, distance 0 + 1: the last
  // byte repeated.
  const std::string in = Bytes({0, 'z', 224, 3, 0});
  std::string out(13, '\0');
  ASSERT_EQ(LzfDecompress(in, out.data(), out.size()), 13u);
  EXPECT_EQ(out, std::string(13, 'z'));
}

TEST(LzfDecompress, CorruptOrOversizedStreamsGiveZero) {
  std::string out(16, '\0');
  // A reference 4 behind the start of the output.
  EXPECT_EQ(LzfDecompress(Bytes({0, 'a', 32, 3}), out.data(), out.size()), 0u);
  // A literal run longer than the input holds.
  EXPECT_EQ(LzfDecompress(Bytes({5, 'a', 'b'}), out.data(), out.size()), 0u);
  // A reference without its distance byte.
  EXPECT_EQ(LzfDecompress(Bytes({0, 'a', 32}), out.data(), out.size()), 0u);
  // More output than the buffer: "abc" into 2 bytes.
  EXPECT_EQ(LzfDecompress(Bytes({2, 'a', 'b', 'c'}), out.data(), 2), 0u);
}

const std::string kHeader =
    "VERSION 0.7\nFIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 1\n"
    "WIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA binary\n";

TEST(ParseHeaderPrefix, WaitsForTheDataLinesNewline) {
  for (const std::size_t cut : {std::size_t{0}, std::size_t{20}, kHeader.size() - 1}) {
    const StatusOr<std::optional<Header>> prefix = ParseHeaderPrefix(kHeader.substr(0, cut), 100);
    ASSERT_TRUE(prefix.ok()) << prefix.status().message();
    EXPECT_FALSE(prefix->has_value()) << cut;
  }
  const StatusOr<std::optional<Header>> whole = ParseHeaderPrefix(kHeader, 100);
  ASSERT_TRUE(whole.ok() && whole->has_value());
  EXPECT_EQ((*whole)->points, 2u);
  EXPECT_EQ((*whole)->point_bytes, 16u);
  EXPECT_EQ((*whole)->data_offset, kHeader.size());
}

TEST(ParseHeader, ATruncatedHeaderAndTooManyPointsAreErrors) {
  EXPECT_EQ(ParseHeader(kHeader.substr(0, 30), 100).status().code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(ParseHeader(kHeader, 1).status().code(), StatusCode::kResourceExhausted);
}

TEST(ReadPcd, ReadsBackWhatEncodePcdWrote) {
  const std::vector<Point> points = {{0.5f, -0.25f, 1.0f, 10, 20, 30, 255},
                                     {1.5f, 2.0f, 3.0f, 200, 100, 0, 255}};
  const StatusOr<Points> read = ReadPcd(EncodePcd(2, 1, points));
  ASSERT_TRUE(read.ok()) << read.status().message();
  EXPECT_EQ(read->width, 2u);
  EXPECT_EQ(read->height, 1u);
  ASSERT_EQ(read->points.size(), 2u);
  EXPECT_EQ(read->points[1].x, 1.5f);
  EXPECT_EQ(read->points[1].r, 200);
  EXPECT_EQ(read->points[0].b, 30);
}

}  // namespace
}  // namespace relmap::pcd
