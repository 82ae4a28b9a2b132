// An OpenNI2 camera (Kinect, Xtion, …) through PCL's OpenNI2 grabber, when the PCL
// this was built against has OpenNI2. PCL's headers stay in openni2_source.cpp.
#pragma once

#include <atomic>
#include <chrono>
#include <memory>
#include <string>

#include "cloud_source.h"

namespace relmap::robot {

// Whether this build has the OpenNI2 source (PCL's HAVE_OPENNI2).
bool OpenNI2Available();

struct OpenNI2Options {
  // PCL's device id: "" (the first device), "#2" (the second), a URI or a .oni file.
  std::string device;
  // Next() waits this long for a frame.
  std::chrono::milliseconds frame_timeout{10000};
};

// A started grabber as a cloud source. Next() answers the first frame the camera
// delivers after the call (never an older one, so an after cloud is seen after the
// push), packed, organized as captured; DEADLINE_EXCEEDED when none comes in time,
// nullopt on a stop. UNAVAILABLE when the device cannot be opened, UNIMPLEMENTED when
// the build has no OpenNI2.
StatusOr<std::unique_ptr<CloudSource>> OpenOpenNI2Source(const OpenNI2Options& options,
                                                         const std::atomic<bool>* stop);

}  // namespace relmap::robot
