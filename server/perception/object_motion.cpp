// Point-to-plane ICP with a uniform grid for the nearest after-point: the part is a few
// hundred points and the after frame is cut to the part's surroundings, so no search tree is
// worth building.
#include "perception/object_motion.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "perception/grid_cell.h"
#include "perception/point_to_plane.h"

namespace relmap::perception {
namespace {

constexpr int kIterationsPerStage = 30;
// A step that moves the part by less than this (metres) ends a stage.
constexpr double kConverged = 1e-5;
// Damping of each step (Levenberg), in the units of the normal equations' diagonal: a motion
// the part's surface leaves free (a plane's slide along itself) stays where it is instead of
// following the noise.
constexpr double kDamping = 1e-3;

// The after-points in cubic cells of `cell` metres, searched ring by ring outwards from a
// point's own cell: the nearest is usually in the first ring, and the search stops once no
// farther ring can hold a nearer point.
class NearestAfterPoint {
 public:
  NearestAfterPoint(const std::vector<SurfacePoint>& after, float cell)
      : inverse_(1.0F / cell), cell_(cell) {
    for (const SurfacePoint& q : after) {
      cells_[GridCellKey(q.position.x(), q.position.y(), q.position.z(), inverse_)].push_back(&q);
    }
  }

  // The nearest after-point within `distance` of `p`, if any.
  const SurfacePoint* Near(const Eigen::Vector3f& p, float distance) const {
    const SurfacePoint* best = nullptr;
    float best_squared = distance * distance;
    const int rings = static_cast<int>(std::ceil(distance * inverse_));
    for (int ring = 0; ring <= rings; ++ring) {
      for (int dx = -ring; dx <= ring; ++dx) {
        for (int dy = -ring; dy <= ring; ++dy) {
          for (int dz = -ring; dz <= ring; ++dz) {
            if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) != ring) continue;
            const auto it = cells_.find(GridCellKey(
                p.x() + static_cast<float>(dx) * cell_, p.y() + static_cast<float>(dy) * cell_,
                p.z() + static_cast<float>(dz) * cell_, inverse_));
            if (it == cells_.end()) continue;
            for (const SurfacePoint* q : it->second) {
              const float squared = (q->position - p).squaredNorm();
              if (squared <= best_squared) {
                best_squared = squared;
                best = q;
              }
            }
          }
        }
      }
      // Cells beyond this ring are more than ring * cell away.
      const float cleared = static_cast<float>(ring) * cell_;
      if (best != nullptr && best_squared <= cleared * cleared) break;
    }
    return best;
  }

 private:
  float inverse_, cell_;
  std::unordered_map<std::uint64_t, std::vector<const SurfacePoint*>> cells_;
};

// Gauss-Newton steps of point-to-plane ICP pairing up to `distance`: false when fewer than
// half the part pairs up.
bool Refine(const std::vector<Eigen::Vector3f>& part, const NearestAfterPoint& after,
            float distance, Eigen::Isometry3f& motion) {
  for (int iteration = 0; iteration < kIterationsPerStage; ++iteration) {
    PointToPlaneStep step;
    for (const Eigen::Vector3f& p : part) {
      const Eigen::Vector3f moved = motion * p;
      const SurfacePoint* q = after.Near(moved, distance);
      if (q != nullptr) step.Add(moved, q->position, q->normal);
    }
    if (2 * step.pairs() < part.size() || step.pairs() < 6) return false;
    const std::optional<PointToPlaneStep::Increment> increment = step.Solve(kDamping);
    if (!increment) return false;
    motion = increment->motion * motion;
    if (increment->rotation_rad < kConverged && increment->translation_m < kConverged) break;
  }
  return true;
}

}  // namespace

std::vector<SurfacePoint> SurfaceWithin(const std::vector<SeenPoint>& seen, std::uint32_t width,
                                        std::uint32_t height, std::uint32_t step,
                                        const Eigen::Vector3f& lo, const Eigen::Vector3f& hi,
                                        float max_gap) {
  constexpr std::uint32_t kSpan = 2;
  std::vector<SurfacePoint> surface;
  if (seen.size() != static_cast<std::size_t>(width) * height) return surface;
  const auto at = [&](std::uint32_t u, std::uint32_t v) -> const Eigen::Vector3f& {
    return seen[static_cast<std::size_t>(v) * width + u].position;
  };
  step = std::max<std::uint32_t>(1, step);
  for (std::uint32_t v = kSpan; v + kSpan < height; v += step) {
    for (std::uint32_t u = kSpan; u + kSpan < width; u += step) {
      const Eigen::Vector3f& p = at(u, v);
      if (!p.allFinite() || (p.array() < lo.array()).any() || (p.array() > hi.array()).any()) {
        continue;
      }
      const Eigen::Vector3f right = at(u + kSpan, v) - at(u - kSpan, v);
      const Eigen::Vector3f down = at(u, v + kSpan) - at(u, v - kSpan);
      if (!right.allFinite() || !down.allFinite() || right.norm() > 2 * max_gap ||
          down.norm() > 2 * max_gap) {
        continue;
      }
      const Eigen::Vector3f n = right.cross(down);
      if (n.norm() > 0) surface.push_back({p, n.normalized()});
    }
  }
  return surface;
}

std::optional<ObjectMotion> FitObjectMotion(const std::vector<Eigen::Vector3f>& part,
                                            const std::vector<SurfacePoint>& after, float reach,
                                            float tolerance) {
  if (part.size() < 6 || after.empty() || !(reach > 0) || !(tolerance > 0)) return std::nullopt;
  ObjectMotion fit;
  const NearestAfterPoint grid(after, tolerance);
  if (!Refine(part, grid, reach, fit.after_from_before) ||
      !Refine(part, grid, tolerance, fit.after_from_before)) {
    return std::nullopt;
  }
  std::size_t inliers = 0;
  for (const Eigen::Vector3f& p : part) {
    inliers += grid.Near(fit.after_from_before * p, tolerance) != nullptr;
  }
  fit.inlier_share = static_cast<double>(inliers) / static_cast<double>(part.size());
  if (2 * inliers < part.size()) return std::nullopt;
  return fit;
}

}  // namespace relmap::perception
