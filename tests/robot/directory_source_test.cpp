// The directory source: PCD files in name order, once each, and waiting for more.
#include "directory_source.h"

#include <gtest/gtest.h>

#include <fstream>
#include <thread>

#include "integration/test_support.h"

namespace relmap::robot {
namespace {

using std::chrono::milliseconds;

void Write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

std::string NextPcd(DirectorySource& source) {
  StatusOr<std::optional<SourceFrame>> frame = source.Next();
  EXPECT_TRUE(frame.ok()) << frame.status().message();
  if (!frame.ok() || !frame->has_value()) return "<none>";
  EXPECT_FALSE((*frame)->truth);
  return (*frame)->cloud.pcd();
}

TEST(DirectorySource, ReadsPcdFilesInNameOrderOnceEach) {
  relmap::testing::TemporaryDirectory directory;
  Write(directory.path() + "/frame-002.pcd", "two");
  Write(directory.path() + "/frame-001.pcd", "one");
  Write(directory.path() + "/notes.txt", "not a cloud");
  DirectorySource source(directory.path(), {});
  EXPECT_EQ(NextPcd(source), "one");
  EXPECT_EQ(NextPcd(source), "two");
  EXPECT_EQ(NextPcd(source), "<none>");
}

TEST(DirectorySource, WaitsForANewFile) {
  relmap::testing::TemporaryDirectory directory;
  DirectorySource::Options options;
  options.wait_for_files = true;
  options.poll = milliseconds(10);
  DirectorySource source(directory.path(), options);
  std::thread camera([&] {
    std::this_thread::sleep_for(milliseconds(100));
    Write(directory.path() + "/late.pcd.partial", "late");
    std::rename((directory.path() + "/late.pcd.partial").c_str(),
                (directory.path() + "/late.pcd").c_str());
  });
  EXPECT_EQ(NextPcd(source), "late");
  camera.join();
}

TEST(DirectorySource, AWaitEndsAtItsTimeoutOrTheStopFlag) {
  relmap::testing::TemporaryDirectory directory;
  DirectorySource::Options options;
  options.wait_for_files = true;
  options.poll = milliseconds(10);
  options.wait_timeout = milliseconds(50);
  DirectorySource timed(directory.path(), options);
  EXPECT_EQ(NextPcd(timed), "<none>");

  const std::atomic<bool> stop{true};
  options.wait_timeout = milliseconds(0);
  DirectorySource stopped(directory.path(), options, &stop);
  EXPECT_EQ(NextPcd(stopped), "<none>");
}

TEST(DirectorySource, AMissingDirectoryIsNotFound) {
  DirectorySource source("/nonexistent/relmap-clouds", {});
  StatusOr<std::optional<SourceFrame>> frame = source.Next();
  ASSERT_FALSE(frame.ok());
  EXPECT_EQ(frame.status().code(), StatusCode::kNotFound);
}

}  // namespace
}  // namespace relmap::robot
