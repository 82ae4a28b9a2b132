// The synthetic cloud is built by the perception layer and packed by hand here, so
// that the tests that include test_support.h need no perception header.
#include "integration/test_support.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "perception/synthetic_tabletop.h"

namespace relmap::testing {

v1::Cloud PackedTabletop(std::uint32_t width, std::uint32_t height, std::uint32_t seed) {
  perception::SyntheticTabletopOptions options;
  options.width = width;
  options.height = height;
  options.seed = seed;
  const perception::SyntheticTabletop scene = perception::MakeSyntheticTabletop(options);
  std::string bytes;
  bytes.reserve(static_cast<std::size_t>(width) * height * 16);
  for (const perception::CloudPoint& p : scene.cloud.points()) {
    char record[16];
    std::memcpy(record, &p.x, 4), std::memcpy(record + 4, &p.y, 4),
        std::memcpy(record + 8, &p.z, 4);
    record[12] = static_cast<char>(p.r), record[13] = static_cast<char>(p.g);
    record[14] = static_cast<char>(p.b), record[15] = static_cast<char>(p.a);
    bytes.append(record, 16);
  }
  v1::Cloud cloud;
  cloud.mutable_packed()->set_width(width);
  cloud.mutable_packed()->set_height(height);
  cloud.mutable_packed()->set_points(std::move(bytes));
  return cloud;
}

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in.good()) << "cannot open " << path;
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_FALSE(bytes.empty()) << path << " is empty or unreadable";
  return bytes;
}

TemporaryDirectory::TemporaryDirectory() {
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = "relmap_";
  if (test != nullptr) name += std::string(test->test_suite_name()) + "_" + test->name() + "_";
  name += std::to_string(::getpid());
  for (char& c : name) {
    if (c == '/') c = '_';  // parameterised tests have slashes in their names
  }
  const std::filesystem::path directory = std::filesystem::path(::testing::TempDir()) / name;
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  path_ = directory.string();
}

TemporaryDirectory::~TemporaryDirectory() {
  std::error_code ignored;  // a leftover directory is not worth failing a test over
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace relmap::testing
