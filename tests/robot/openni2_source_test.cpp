// The OpenNI2 source on a machine without a camera: an error that says so, not a crash
// or a hang.
#include "openni2_source.h"

#include <gtest/gtest.h>

namespace relmap::robot {
namespace {

TEST(OpenNI2Source, WithoutADeviceOpeningIsUnavailableOrTheBuildSaysItHasNoOpenNI2) {
  OpenNI2Options options;
  options.device = "#9";  // a ninth camera: there is none, on a test machine or a lab's
  StatusOr<std::unique_ptr<CloudSource>> source = OpenOpenNI2Source(options, nullptr);
  ASSERT_FALSE(source.ok());
  EXPECT_EQ(source.status().code(),
            OpenNI2Available() ? StatusCode::kUnavailable : StatusCode::kUnimplemented)
      << source.status().message();
  if (OpenNI2Available()) {
    EXPECT_NE(source.status().message().find("\"#9\""), std::string::npos)
        << source.status().message();
  }
}

}  // namespace
}  // namespace relmap::robot
