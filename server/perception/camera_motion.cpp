// Registration by projective point-to-plane ICP (organized clouds) or PCL's ICP (others);
// intrinsics by least squares.
#include "perception/camera_motion.h"

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/registration/icp.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "perception/point_to_plane.h"

namespace relmap::perception {
namespace {

using XyzCloud = pcl::PointCloud<pcl::PointXYZ>;

// About `count` of the cloud's finite points, every k-th in storage order. Not a voxel
// grid: the centroids of two frames' cells snap to the same grid, which holds ICP at the
// identity (1→2 of kinect_static_seq_* came out 0.3 degrees instead of 0.8).
XyzCloud::Ptr Sampled(const Cloud& cloud, std::size_t count) {
  const std::size_t stride = std::max<std::size_t>(1, cloud.valid_points() / count);
  XyzCloud::Ptr points(new XyzCloud);
  points->reserve(cloud.valid_points() / stride + 1);
  std::size_t seen = 0;
  for (const pcl::PointXYZRGBA& p : cloud.pcl()) {
    if (!pcl::isFinite(p)) continue;
    if (seen++ % stride == 0) points->push_back({p.x, p.y, p.z});
  }
  return points;
}

// Fits value = scale * ratio + offset over the pairs; nullopt if the fit is off by more
// than half a pixel anywhere on average.
std::optional<std::pair<double, double>> FitAxis(const std::vector<double>& ratio,
                                                 const std::vector<double>& pixel) {
  const auto n = static_cast<Eigen::Index>(ratio.size());
  if (n < 16) return std::nullopt;
  Eigen::MatrixXd a(n, 2);
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    a(i, 0) = ratio[static_cast<std::size_t>(i)];
    a(i, 1) = 1.0;
    b[i] = pixel[static_cast<std::size_t>(i)];
  }
  const Eigen::Vector2d fit = a.colPivHouseholderQr().solve(b);
  const double rms = std::sqrt((a * fit - b).squaredNorm() / static_cast<double>(n));
  if (!(fit[0] > 0) || !(rms < 0.5)) return std::nullopt;
  return std::make_pair(fit[0], fit[1]);
}

// The before frame's normal at pixel (u, v), from central differences 3 pixels apart (one
// pixel apart, the depth steps of quantisation tilt it); nullopt at the border, next to
// holes and across depth jumps (neighbours farther than `max_gap`).
std::optional<Eigen::Vector3f> NormalAt(const Cloud& cloud, std::uint32_t u, std::uint32_t v,
                                        float max_gap) {
  constexpr std::uint32_t kSpan = 3;
  if (u < kSpan || v < kSpan || u + kSpan >= cloud.width() || v + kSpan >= cloud.height()) {
    return std::nullopt;
  }
  const auto at = [&cloud](std::uint32_t x, std::uint32_t y) {
    const CloudPoint p = cloud.point(static_cast<std::size_t>(y) * cloud.width() + x);
    return Eigen::Vector3f(p.x, p.y, p.z);
  };
  const Eigen::Vector3f p = at(u, v);
  const Eigen::Vector3f right = at(u + kSpan, v) - at(u - kSpan, v);
  const Eigen::Vector3f down = at(u, v + kSpan) - at(u, v - kSpan);
  if (!p.allFinite() || !right.allFinite() || !down.allFinite()) return std::nullopt;
  if (right.norm() > 2 * max_gap || down.norm() > 2 * max_gap) return std::nullopt;
  const Eigen::Vector3f n = right.cross(down);
  if (!(n.norm() > 0)) return std::nullopt;
  return n.normalized();
}

// Point-to-plane ICP with projective association (Newcombe et al. 2011, KinectFusion): each
// sampled after-point, moved by the current estimate, is paired with the before-point on its
// pixel. No search tree, and a few iterations suffice for the small motions this is for.
CameraMotion ProjectiveIcp(const Cloud& before, const Intrinsics& k, const Cloud& after,
                           std::size_t samples, float max_distance) {
  constexpr int kIterations = 20;
  const std::size_t stride = std::max<std::size_t>(1, after.valid_points() / samples);
  std::vector<Eigen::Vector3f> source;
  std::size_t seen = 0;
  for (const pcl::PointXYZRGBA& p : after.pcl()) {
    if (pcl::isFinite(p) && seen++ % stride == 0) source.emplace_back(p.x, p.y, p.z);
  }
  CameraMotion motion;
  Eigen::Isometry3f estimate = Eigen::Isometry3f::Identity();
  for (int iteration = 0; iteration < kIterations; ++iteration) {
    PointToPlaneStep step;
    for (const Eigen::Vector3f& q : source) {
      const Eigen::Vector3f moved = estimate * q;
      const std::optional<Pixel> pixel = PixelOf(k, moved, before.width(), before.height());
      if (!pixel) continue;
      const auto [pu, pv] = *pixel;
      const CloudPoint target = before.point(static_cast<std::size_t>(pv) * before.width() + pu);
      const Eigen::Vector3f p(target.x, target.y, target.z);
      if (!p.allFinite() || (moved - p).norm() > max_distance) continue;
      const std::optional<Eigen::Vector3f> n = NormalAt(before, pu, pv, max_distance);
      if (!n) continue;
      // Huber weight at 1 cm: what moved in the push pulls less than the static scene.
      const double residual = n->dot(moved - p);
      step.Add(moved, p, *n, std::min(1.0, 0.01 / std::max(1e-9, std::fabs(residual))));
    }
    if (step.pairs() < 100) return motion;
    const std::optional<PointToPlaneStep::Increment> increment = step.Solve();
    if (!increment) return motion;
    estimate = increment->motion * estimate;
    if (increment->rotation_rad < 1e-6 && increment->translation_m < 1e-6) break;
  }
  motion.converged = true;
  motion.before_from_after = estimate;
  return motion;
}

}  // namespace

std::optional<Intrinsics> IntrinsicsOf(const Cloud& cloud) {
  if (!cloud.organized()) return std::nullopt;
  std::vector<double> xz, u, yz, v;
  // Every 7th pixel of every 7th row: a few thousand pairs, spread over the image.
  for (std::uint32_t row = 0; row < cloud.height(); row += 7) {
    for (std::uint32_t col = 0; col < cloud.width(); col += 7) {
      const CloudPoint p = cloud.point(static_cast<std::size_t>(row) * cloud.width() + col);
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !(p.z > 0)) continue;
      xz.push_back(p.x / p.z);
      u.push_back(col);
      yz.push_back(p.y / p.z);
      v.push_back(row);
    }
  }
  const auto horizontal = FitAxis(xz, u);
  const auto vertical = FitAxis(yz, v);
  if (!horizontal || !vertical) return std::nullopt;
  return Intrinsics{horizontal->first, vertical->first, horizontal->second, vertical->second};
}

namespace {

// Point-to-point ICP with a search tree, for clouds without a pixel grid. It takes small
// steps: PCL's default criteria (a step under 0.26 degrees, a relative MSE change under
// 1e-5) stopped it at a third of the 1.2 degrees between kinect_static_seq_1 and _3, so only
// the iteration bound and tiny steps stop it here.
CameraMotion TreeIcp(const Cloud& before, const Cloud& after, std::size_t samples,
                     float max_distance) {
  CameraMotion motion;
  const XyzCloud::Ptr source = Sampled(after, samples);
  const XyzCloud::Ptr target = Sampled(before, 4 * samples);
  if (source->size() < 16 || target->size() < 16) return motion;
  pcl::IterativeClosestPoint<pcl::PointXYZ, pcl::PointXYZ> icp;
  icp.setInputSource(source);
  icp.setInputTarget(target);
  icp.setMaxCorrespondenceDistance(max_distance);
  icp.setMaximumIterations(60);
  icp.setTransformationEpsilon(1e-10);
  icp.setTransformationRotationEpsilon(1.0 - 1e-10);
  icp.setEuclideanFitnessEpsilon(1e-12);
  XyzCloud aligned;
  icp.align(aligned);
  if (!icp.hasConverged()) return motion;
  motion.converged = true;
  motion.before_from_after.matrix() = icp.getFinalTransformation();
  return motion;
}

}  // namespace

CameraMotion EstimateCameraMotion(const Cloud& before, const Cloud& after, std::size_t samples,
                                  float max_distance) {
  return EstimateCameraMotion(before, IntrinsicsOf(before), after, samples, max_distance);
}

CameraMotion EstimateCameraMotion(const Cloud& before, const std::optional<Intrinsics>& k,
                                  const Cloud& after, std::size_t samples, float max_distance) {
  CameraMotion motion = k ? ProjectiveIcp(before, *k, after, samples, max_distance)
                          : TreeIcp(before, after, samples, max_distance);
  if (motion.converged) {
    const Eigen::AngleAxisf rotation(motion.before_from_after.linear());
    motion.rotation_deg = std::fabs(rotation.angle()) * 180.0 / 3.14159265358979323846;
    motion.translation_m = motion.before_from_after.translation().norm();
  }
  return motion;
}

std::optional<Pixel> PixelOf(const Intrinsics& k, const Eigen::Vector3f& point, std::uint32_t width,
                             std::uint32_t height) {
  if (!(point.z() > 0)) return std::nullopt;
  const double u = std::round(k.fx * point.x() / point.z() + k.cx);
  const double v = std::round(k.fy * point.y() / point.z() + k.cy);
  if (!(u >= 0 && v >= 0 && u < width && v < height)) return std::nullopt;
  return Pixel{static_cast<std::uint32_t>(u), static_cast<std::uint32_t>(v)};
}

std::vector<SeenPoint> ReprojectInto(const Cloud& after, const Eigen::Isometry3f& motion,
                                     const Intrinsics& k, std::uint32_t width,
                                     std::uint32_t height) {
  constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
  std::vector<SeenPoint> image(static_cast<std::size_t>(width) * height,
                               SeenPoint{Eigen::Vector3f::Constant(kNan), {}});
  for (const pcl::PointXYZRGBA& p : after.pcl()) {
    if (!pcl::isFinite(p)) continue;
    const Eigen::Vector3f q = motion * Eigen::Vector3f(p.x, p.y, p.z);
    const std::optional<Pixel> at = PixelOf(k, q, width, height);
    if (!at) continue;
    SeenPoint& pixel = image[static_cast<std::size_t>(at->v) * width + at->u];
    // NaN or farther: the nearer point hides it.
    if (!(pixel.position.z() <= q.z())) pixel = {q, {p.r, p.g, p.b}};
  }
  return image;
}

}  // namespace relmap::perception
