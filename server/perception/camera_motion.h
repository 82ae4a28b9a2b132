// The motion of the camera between two frames of a scene that mostly stayed put, and the
// after frame seen from the before frame's pixels. A robot's head settles, a hand-held or
// arm-mounted camera drifts: the three frames of kinect_static_seq_* are up to 1.2 degrees
// and 1.3 cm apart, which moves a surface at 1 m by ~10 pixels.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "perception/cloud.h"

namespace relmap::perception {

// A pinhole camera's intrinsics, in pixels.
struct Intrinsics {
  double fx = 0, fy = 0, cx = 0, cy = 0;
};

// The intrinsics an organized cloud's points imply (u = fx x / z + cx, v = fy y / z + cy, by
// least squares); nullopt when the cloud is not organized or its points do not fit a
// pinhole camera within half a pixel (a registered or resampled cloud).
std::optional<Intrinsics> IntrinsicsOf(const Cloud& cloud);

struct CameraMotion {
  // Maps after-frame coordinates into the before frame.
  Eigen::Isometry3f before_from_after = Eigen::Isometry3f::Identity();
  bool converged = false;
  double rotation_deg = 0;
  double translation_m = 0;
};

// ICP of about `samples` after-frame points onto four times as many before-frame points;
// correspondences farther than `max_distance` (what moved) are left out. Throws what PCL
// throws.
CameraMotion EstimateCameraMotion(const Cloud& before, const Cloud& after, std::size_t samples,
                                  float max_distance);
// The same with the before frame's intrinsics already read (IntrinsicsOf(before)).
CameraMotion EstimateCameraMotion(const Cloud& before, const std::optional<Intrinsics>& intrinsics,
                                  const Cloud& after, std::size_t samples, float max_distance);

// The pixel a point (in the camera's frame) projects to, rounded to the nearest; nullopt
// behind the camera or outside a width x height image.
struct Pixel {
  std::uint32_t u, v;
};
std::optional<Pixel> PixelOf(const Intrinsics& k, const Eigen::Vector3f& point, std::uint32_t width,
                             std::uint32_t height);

// A point of a re-projected frame, with its colour.
struct SeenPoint {
  Eigen::Vector3f position;
  std::array<std::uint8_t, 3> rgb{};
};

// The after frame's points moved by `motion` and projected into a width x height image with
// `intrinsics`, nearest point per pixel; NaN positions where none falls.
std::vector<SeenPoint> ReprojectInto(const Cloud& after, const Eigen::Isometry3f& motion,
                                     const Intrinsics& intrinsics, std::uint32_t width,
                                     std::uint32_t height);

}  // namespace relmap::perception
