// Decoding of PCD (every DATA variant, rgb and rgba, organized or not) and of the packed
// layout; malformed input of every kind gives a clear error and never a crash.
#include "perception/decode.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <pcl/io/lzf.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "test_data.h"

namespace relmap::perception {
namespace {

using ::testing::HasSubstr;

const float kNaN = std::numeric_limits<float>::quiet_NaN();

std::vector<CloudPoint> SamplePoints() {
  return {{0.1f, 0.2f, 1.0f, 255, 0, 0, 255},
          {kNaN, kNaN, kNaN, 0, 0, 0, 0},
          {-0.3f, 0.25f, 1.5f, 10, 200, 30, 128},
          {0.0f, -0.1f, 0.8f, 1, 2, 3, 4}};
}

std::uint32_t Packed(const CloudPoint& p, bool alpha) {
  return (alpha ? static_cast<std::uint32_t>(p.a) << 24 : 0u) |
         static_cast<std::uint32_t>(p.r) << 16 | static_cast<std::uint32_t>(p.g) << 8 | p.b;
}

std::string Header(const std::string& colour, const std::string& colour_type,
                   const std::string& data, int width, int height) {
  return "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z " + colour + "\nSIZE 4 4 4 4\nTYPE F F F " +
         colour_type + "\nCOUNT 1 1 1 1\nWIDTH " + std::to_string(width) + "\nHEIGHT " +
         std::to_string(height) + "\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " +
         std::to_string(static_cast<long long>(width) * height) + "\nDATA " + data + "\n";
}

// Point-major 16-byte records x y z colour.
std::string BinaryBody(const std::vector<CloudPoint>& points, bool alpha) {
  std::string body;
  for (const CloudPoint& p : points) {
    const std::uint32_t c = Packed(p, alpha);
    body.append(reinterpret_cast<const char*>(&p.x), 12);
    body.append(reinterpret_cast<const char*>(&c), 4);
  }
  return body;
}

std::string CompressedBody(const std::vector<CloudPoint>& points, bool alpha) {
  std::string soa;  // field-major, as PCL writes binary_compressed
  for (int field = 0; field < 4; ++field) {
    for (const CloudPoint& p : points) {
      const std::uint32_t c = Packed(p, alpha);
      const float* xyz = &p.x;
      soa.append(field < 3 ? reinterpret_cast<const char*>(xyz + field)
                           : reinterpret_cast<const char*>(&c),
                 4);
    }
  }
  std::vector<char> out(soa.size() * 2 + 64);
  const auto compressed = pcl::lzfCompress(soa.data(), static_cast<unsigned>(soa.size()),
                                           out.data(), static_cast<unsigned>(out.size()));
  const std::uint32_t sizes[2] = {compressed, static_cast<std::uint32_t>(soa.size())};
  std::string body(reinterpret_cast<const char*>(sizes), 8);
  body.append(out.data(), compressed);
  return body;
}

std::string AsciiBody(const std::vector<CloudPoint>& points, bool alpha) {
  std::string body;
  for (const CloudPoint& p : points) {
    char line[128];
    const std::uint32_t packed = Packed(p, alpha);
    if (alpha) {
      std::snprintf(line, sizeof(line), "%.9g %.9g %.9g %u\n", p.x, p.y, p.z, packed);
    } else {  // TYPE F: PCL writes the float with the packed bits
      float as_float;
      std::memcpy(&as_float, &packed, 4);
      std::snprintf(line, sizeof(line), "%.9g %.9g %.9g %.9g\n", p.x, p.y, p.z, as_float);
    }
    body += line;
  }
  return body;
}

void ExpectSamePoints(const Cloud& cloud, const std::vector<CloudPoint>& expected, bool alpha) {
  ASSERT_EQ(cloud.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const CloudPoint p = cloud.point(i);
    if (std::isnan(expected[i].x)) {
      EXPECT_TRUE(std::isnan(p.x) && std::isnan(p.y) && std::isnan(p.z)) << i;
      continue;
    }
    EXPECT_EQ(p.x, expected[i].x) << i;
    EXPECT_EQ(p.y, expected[i].y) << i;
    EXPECT_EQ(p.z, expected[i].z) << i;
    EXPECT_EQ(p.r, expected[i].r) << i;
    EXPECT_EQ(p.g, expected[i].g) << i;
    EXPECT_EQ(p.b, expected[i].b) << i;
    EXPECT_EQ(p.a, alpha ? expected[i].a : 255) << i;
  }
}

struct Variant {
  std::string data;
  bool alpha;
  int width, height;
};

class PcdVariants : public ::testing::TestWithParam<Variant> {};

TEST_P(PcdVariants, DecodesEveryPointAndColour) {
  const Variant v = GetParam();
  const std::vector<CloudPoint> points = SamplePoints();
  const std::string body = v.data == "ascii"    ? AsciiBody(points, v.alpha)
                           : v.data == "binary" ? BinaryBody(points, v.alpha)
                                                : CompressedBody(points, v.alpha);
  const std::string pcd =
      Header(v.alpha ? "rgba" : "rgb", v.alpha ? "U" : "F", v.data, v.width, v.height) + body;
  StatusOr<Cloud> cloud = DecodePcd(pcd);
  ASSERT_TRUE(cloud.ok()) << cloud.status().message();
  EXPECT_EQ(cloud->width(), static_cast<std::uint32_t>(v.width));
  EXPECT_EQ(cloud->height(), static_cast<std::uint32_t>(v.height));
  EXPECT_EQ(cloud->organized(), v.height > 1);
  EXPECT_EQ(cloud->valid_points(), 3u);
  ExpectSamePoints(*cloud, points, v.alpha);
}

INSTANTIATE_TEST_SUITE_P(AllDataTypes, PcdVariants,
                         ::testing::Values(Variant{"ascii", false, 4, 1},
                                           Variant{"ascii", true, 2, 2},
                                           Variant{"binary", false, 2, 2},
                                           Variant{"binary", true, 4, 1},
                                           Variant{"binary_compressed", false, 4, 1},
                                           Variant{"binary_compressed", true, 2, 2}),
                         // Readable test names: e.g. binary_compressed_rgba_2x2.
                         [](const ::testing::TestParamInfo<Variant>& test_info) {
                           const Variant& v = test_info.param;
                           return v.data + (v.alpha ? "_rgba_" : "_rgb_") +
                                  std::to_string(v.width) + "x" + std::to_string(v.height);
                         });

TEST(DecodePcd, SkipsExtraFieldsAndReadsDoubleCoordinates) {
  std::string pcd =
      "VERSION .7\nFIELDS intensity x y z rgb\nSIZE 2 8 8 8 4\nTYPE U F F F U\n"
      "COUNT 1 1 1 1 1\nWIDTH 1\nHEIGHT 1\nDATA binary\n";
  const std::uint16_t intensity = 7;
  const double xyz[3] = {0.5, -0.25, 2.0};
  const std::uint32_t rgb = 0x00102030;
  pcd.append(reinterpret_cast<const char*>(&intensity), 2);
  pcd.append(reinterpret_cast<const char*>(xyz), 24);
  pcd.append(reinterpret_cast<const char*>(&rgb), 4);
  StatusOr<Cloud> cloud = DecodePcd(pcd);
  ASSERT_TRUE(cloud.ok()) << cloud.status().message();
  const CloudPoint p = cloud->point(0);
  EXPECT_EQ(p.x, 0.5f);
  EXPECT_EQ(p.z, 2.0f);
  EXPECT_EQ(p.r, 0x10);
  EXPECT_EQ(p.b, 0x30);
}

TEST(DecodePcd, ReadsTheRealKinectClouds) {
  RELMAP_LOAD_REAL_CLOUD(cloud, "kinect_static_seq_1.pcd");
  EXPECT_EQ(cloud.width(), 640u);
  EXPECT_EQ(cloud.height(), 480u);
  EXPECT_GT(cloud.valid_points(), 200000u);
  EXPECT_LT(cloud.valid_points(), cloud.size());  // a depth camera leaves holes
}

// The error for `pcd`, which must not decode.
std::string ErrorOf(const std::string& pcd) {
  StatusOr<Cloud> cloud = DecodePcd(pcd);
  EXPECT_FALSE(cloud.ok());
  if (cloud.ok()) return "";
  EXPECT_EQ(cloud.status().code(), StatusCode::kInvalidArgument);
  return cloud.status().message();
}

std::string ValidBinary() {
  return Header("rgb", "F", "binary", 4, 1) + BinaryBody(SamplePoints(), false);
}
std::string ValidCompressed() {
  return Header("rgba", "U", "binary_compressed", 4, 1) + CompressedBody(SamplePoints(), true);
}

TEST(DecodePcdErrors, TruncatedBinaryData) {
  const std::string pcd = ValidBinary();
  EXPECT_THAT(ErrorOf(pcd.substr(0, pcd.size() - 5)), HasSubstr("truncated"));
}

TEST(DecodePcdErrors, TruncatedCompressedData) {
  const std::string pcd = ValidCompressed();
  EXPECT_THAT(ErrorOf(pcd.substr(0, pcd.size() - 3)), HasSubstr("truncated"));
}

TEST(DecodePcdErrors, CompressedSizeThatDisagreesWithTheHeader) {
  std::string pcd = ValidCompressed();
  const std::size_t at = pcd.find("DATA binary_compressed\n") + 23 + 4;
  const std::uint32_t wrong = 1u << 30;
  std::memcpy(&pcd[at], &wrong, 4);
  EXPECT_THAT(ErrorOf(pcd), HasSubstr("uncompressed size"));
}

TEST(DecodePcdErrors, CorruptLzfStream) {
  std::string pcd = ValidCompressed();
  const std::size_t at = pcd.find("DATA binary_compressed\n") + 23 + 8;
  for (std::size_t i = at; i < pcd.size(); ++i) pcd[i] = static_cast<char>(0xff);
  EXPECT_THAT(ErrorOf(pcd), HasSubstr("LZF"));
}

TEST(DecodePcdErrors, MorePointsThanTheLimitAreResourceExhausted) {
  // A limit of the server, not a malformed file: refused before any allocation.
  const StatusOr<Cloud> huge = DecodePcd(Header("rgb", "F", "binary", 2000000000, 2000000000));
  EXPECT_EQ(huge.status().code(), StatusCode::kResourceExhausted);
  EXPECT_THAT(huge.status().message(), HasSubstr("exceeds the limit"));
}

TEST(DecodePcdErrors, AbsurdDeclaredCounts) {
  std::string pcd = ValidBinary();
  pcd.replace(pcd.find("POINTS 4"), 8, "POINTS 5");
  EXPECT_THAT(ErrorOf(pcd), HasSubstr("POINTS 5 differs"));
  pcd = ValidBinary();
  pcd.replace(pcd.find("COUNT 1 1 1 1"), 13, "COUNT 1 1 1 99999999");
  EXPECT_THAT(ErrorOf(pcd), HasSubstr("count"));
  pcd = ValidBinary();
  pcd.replace(pcd.find("WIDTH 4"), 7, "WIDTH -4");
  EXPECT_THAT(ErrorOf(pcd), HasSubstr("WIDTH"));
}

TEST(DecodePcdErrors, WrongSizesAndTypes) {
  std::string pcd = ValidBinary();
  pcd.replace(pcd.find("SIZE 4 4 4 4"), 12, "SIZE 4 4 4 3");
  EXPECT_THAT(ErrorOf(pcd), HasSubstr("size 3"));
  pcd = ValidBinary();
  pcd.replace(pcd.find("SIZE 4 4 4 4"), 12, "SIZE 4 4 4");
  EXPECT_THAT(ErrorOf(pcd), HasSubstr("3 entries for 4 fields"));
  pcd = ValidBinary();
  pcd.replace(pcd.find("TYPE F F F F"), 12, "TYPE F F U F");
  EXPECT_THAT(ErrorOf(pcd), HasSubstr("'z' must be one float"));
  pcd = ValidBinary();
  pcd.replace(pcd.find("TYPE F F F F"), 12, "TYPE F F F X");
  EXPECT_THAT(ErrorOf(pcd), HasSubstr("type 'X'"));
}

TEST(DecodePcdErrors, MissingFieldsAndLines) {
  std::string pcd = ValidBinary();
  pcd.replace(pcd.find("FIELDS x y z rgb"), 16, "FIELDS x y z foo");
  EXPECT_THAT(ErrorOf(pcd), HasSubstr("no colour field"));
  EXPECT_THAT(ErrorOf("VERSION 0.7\nFIELDS x y z rgb\n"), HasSubstr("DATA"));
  EXPECT_THAT(ErrorOf(""), HasSubstr("DATA"));
  EXPECT_THAT(ErrorOf("garbage\n"), HasSubstr("unknown keyword 'garbage'"));
}

TEST(DecodePcdErrors, AsciiWithMissingOrBadValues) {
  const std::string header = Header("rgb", "U", "ascii", 2, 1);
  EXPECT_THAT(ErrorOf(header + "0 0 1 5\n"), HasSubstr("1 points, the header declares 2"));
  EXPECT_THAT(ErrorOf(header + "0 0 1 5\n0 0 1\n"), HasSubstr("expected 4 values"));
  EXPECT_THAT(ErrorOf(header + "0 0 1 5\n0 0 1 5 6\n"), HasSubstr("expected 4 values"));
  EXPECT_THAT(ErrorOf(header + "0 0 1 5\n0 zero 1 5\n"), HasSubstr("'zero' is not a number"));
}

TEST(DecodePcdErrors, NonFiniteEverywhereIsACloudWithoutValidPoint) {
  const std::string header = Header("rgb", "U", "ascii", 3, 1);
  EXPECT_THAT(ErrorOf(header + "nan nan nan 0\ninf 0 1 0\n0 -inf 1 0\n"),
              HasSubstr("no valid (finite) point"));
}

TEST(DecodePcdErrors, AbsurdCoordinates) {
  const std::string header = Header("rgb", "U", "ascii", 1, 1);
  EXPECT_THAT(ErrorOf(header + "1e30 0 1 0\n"), HasSubstr("coordinate limit"));
}

TEST(DecodePcd, InfiniteCoordinatesBecomeHoles) {
  const std::string header = Header("rgb", "U", "ascii", 2, 1);
  StatusOr<Cloud> cloud = DecodePcd(header + "inf 0 1 0\n0 0 1 0\n");
  ASSERT_TRUE(cloud.ok()) << cloud.status().message();
  EXPECT_EQ(cloud->valid_points(), 1u);
  EXPECT_TRUE(std::isnan(cloud->point(0).x));
}

TEST(DecodePcdErrors, RandomCorruptionNeverCrashes) {
  // Flip bytes of valid files at random: each result is a cloud or a clear error.
  std::mt19937 rng(7);
  for (const std::string& valid : {ValidBinary(), ValidCompressed()}) {
    for (int trial = 0; trial < 500; ++trial) {
      std::string pcd = valid;
      std::uniform_int_distribution<std::size_t> at(0, pcd.size() - 1);
      for (int k = 0; k < 4; ++k) pcd[at(rng)] = static_cast<char>(rng());
      if (trial % 3 == 0) pcd.resize(at(rng));
      StatusOr<Cloud> cloud = DecodePcd(pcd);
      if (!cloud.ok()) {
        EXPECT_FALSE(cloud.status().message().empty());
      }
    }
  }
}

TEST(DecodePacked, RoundTripsSixteenBytesPerPoint) {
  const std::vector<CloudPoint> points = SamplePoints();
  std::string bytes;
  for (const CloudPoint& p : points) {
    bytes.append(reinterpret_cast<const char*>(&p.x), 12);
    bytes.append({static_cast<char>(p.r), static_cast<char>(p.g), static_cast<char>(p.b),
                  static_cast<char>(p.a)});
  }
  StatusOr<Cloud> cloud = DecodePacked(bytes, 2, 2);
  ASSERT_TRUE(cloud.ok()) << cloud.status().message();
  EXPECT_TRUE(cloud->organized());
  ExpectSamePoints(*cloud, points, /*alpha=*/true);
}

TEST(DecodePacked, RejectsWrongSizesAndLimits) {
  const std::string bytes(64, '\0');
  EXPECT_THAT(DecodePacked(bytes, 5, 1).status().message(), HasSubstr("need 80 bytes"));
  EXPECT_THAT(DecodePacked(bytes, 0, 4).status().message(), HasSubstr("must be > 0"));
  EXPECT_THAT(DecodePacked(bytes, 100000, 100000).status().message(), HasSubstr("allowed"));
  // (2^32 - 1)^2 points overflow a signed 64-bit product: the fuzzer's crasher.
  const StatusOr<Cloud> huge = DecodePacked(bytes, 4294967295u, 4294967295u);
  EXPECT_EQ(huge.status().code(), StatusCode::kResourceExhausted);
  EXPECT_THAT(huge.status().message(), HasSubstr("18446744065119617025 points"));
  DecodeLimits small;
  small.max_points = 3;
  EXPECT_THAT(DecodePacked(bytes, 4, 1, small).status().message(), HasSubstr("allowed"));
}

}  // namespace
}  // namespace relmap::perception
