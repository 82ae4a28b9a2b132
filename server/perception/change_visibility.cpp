// relmap's labelling (docs/method.md §5.1): every point of the target is looked up in the
// after frame along its own pixel's ray. A static camera sees a static surface at the same
// pixels again, within its noise; where the target left, the ray now reaches what was
// behind it. Counting points, not fitting them, keeps a partly vacated target (a ball that
// rolled 2 cm, a brick slid along its length) from failing a fitness bound, and judging
// the distance by the camera's noise model keeps the same configuration right at any
// depth and resolution.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "perception/camera_motion.h"
#include "perception/change_methods.h"
#include "perception/grid_cell.h"
#include "perception/perception_config.h"

namespace relmap::perception {
namespace {

Eigen::Vector3f Position(const CloudPoint& p) { return {p.x, p.y, p.z}; }

bool Finite(const CloudPoint& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// How far apart two observations of one static surface point at depth z may be: both are
// noisy (sqrt 2 sigma) and each is quantised (a step, at worst).
double Tolerance(const ChangeDetectorConfig& config, double z) {
  const double depth = std::fabs(z);
  return config.tolerance_sigmas * std::sqrt(2.0) * config.noise.Sigma(depth) +
         config.noise.Step(depth);
}

// How far, and over how many pixels each way, a point is looked for in the after frame
// before it counts as moved: the camera's noise, or the client's smallest motion that counts
// where that is larger (a motion of m at depth z spans m fx / z pixels).
struct Reach {
  double distance;
  int window;
};

Reach NoiseReach(const ChangeDetectorConfig& config, double z) {
  return {Tolerance(config, z), config.search_window};
}

Reach MotionReach(const ChangeDetectorConfig& config, double fx, double z) {
  const double pixels = std::ceil(config.min_motion * fx / std::max(std::fabs(z), 1e-3));
  return {config.min_motion, static_cast<int>(std::min<double>(pixels, kMaxMotionWindow))};
}

enum class Seen { kSupported, kVacated, kOccluded, kUnknown };

// The per-channel gain that maps the after frame's colours onto the before frame's: auto
// exposure and white balance change between frames (the simulated Kinect draws 3 % and 2 %
// per frame). From the pixels whose depth agrees, every 8th.
Eigen::Array3d ColourGain(const Cloud& before, const std::vector<SeenPoint>& after,
                          const ChangeDetectorConfig& config) {
  Eigen::Array3d sum_before = Eigen::Array3d::Zero(), sum_after = Eigen::Array3d::Zero();
  for (std::size_t i = 0; i < after.size(); i += 8) {
    const CloudPoint p = before.point(i);
    const Eigen::Vector3f& q = after[i].position;
    if (!Finite(p) || !q.allFinite()) continue;
    if (std::fabs(q.z() - p.z) > Tolerance(config, p.z)) continue;
    sum_before += Eigen::Array3d(p.r, p.g, p.b);
    sum_after += Eigen::Array3d(after[i].rgb[0], after[i].rgb[1], after[i].rgb[2]);
  }
  Eigen::Array3d gain = Eigen::Array3d::Ones();
  for (int c = 0; c < 3; ++c) {
    if (sum_after[c] > 0 && sum_before[c] > 0) gain[c] = sum_before[c] / sum_after[c];
  }
  return gain;
}

// What the after frame (in the before frame's pixels) shows of the before-point `p`
// (position, colour) at `index`: still there if a point within `tolerance` in a window
// around the pixel looks the same (every channel within `colour_tolerance` once the gain is
// applied; 0 turns colour off); seen through if the surface there now looks different (it
// slid in its own plane: a wood grain, a print) or if the point on the pixel's own ray is
// farther; hidden if that point is nearer.
Seen SeenAlongRay(const std::vector<SeenPoint>& after, std::uint32_t width, std::uint32_t height,
                  std::size_t index, const CloudPoint& before_point, double tolerance, int window,
                  const Eigen::Array3d& gain, double colour_tolerance) {
  const Eigen::Vector3f p = Position(before_point);
  const Eigen::Array3d colour(before_point.r, before_point.g, before_point.b);
  const auto w = static_cast<std::int64_t>(width);
  const auto h = static_cast<std::int64_t>(height);
  const auto u = static_cast<std::int64_t>(index) % w;
  const auto v = static_cast<std::int64_t>(index) / w;
  const auto squared = static_cast<float>(tolerance * tolerance);
  bool surface_there = false;
  for (std::int64_t y = std::max<std::int64_t>(0, v - window); y <= std::min(h - 1, v + window);
       ++y) {
    for (std::int64_t x = std::max<std::int64_t>(0, u - window); x <= std::min(w - 1, u + window);
         ++x) {
      const SeenPoint& q = after[static_cast<std::size_t>(y * w + x)];
      if (!q.position.allFinite() || (q.position - p).squaredNorm() > squared) continue;
      surface_there = true;
      const Eigen::Array3d seen(q.rgb[0], q.rgb[1], q.rgb[2]);
      if (colour_tolerance <= 0 || ((seen * gain - colour).abs() <= colour_tolerance).all()) {
        return Seen::kSupported;
      }
    }
  }
  if (surface_there) return Seen::kVacated;
  const Eigen::Vector3f& q = after[index].position;
  if (!q.allFinite()) return Seen::kUnknown;  // a hole (shadow, edge, range) tells nothing
  if (q.z() > p.z()) return Seen::kVacated;   // the ray now goes past where the point was
  return Seen::kOccluded;
}

// The share of the before frame's points (every 16th) that `after` still shows within the
// tolerance, by geometry alone.
double SupportedShare(const Cloud& before, const std::vector<SeenPoint>& after,
                      const ChangeDetectorConfig& config) {
  std::size_t points = 0, supported = 0;
  for (std::size_t i = 0; i < before.size(); i += 16) {
    const CloudPoint p = before.point(i);
    if (!Finite(p)) continue;
    ++points;
    supported += SeenAlongRay(after, before.width(), before.height(), i, p, Tolerance(config, p.z),
                              config.search_window, Eigen::Array3d::Ones(), 0) == Seen::kSupported;
  }
  return points == 0 ? 0.0 : static_cast<double>(supported) / static_cast<double>(points);
}

// Clouds without a shared pixel grid: a point is still there when an after-point lies
// within its tolerance, vacated otherwise (occlusion cannot be told apart).
class NearbyAfterPoints {
 public:
  NearbyAfterPoints(const Cloud& after, const Eigen::Isometry3f& motion, const Eigen::Vector3f& lo,
                    const Eigen::Vector3f& hi, float cell)
      : inverse_(1.0f / cell), cell_(cell) {
    for (std::size_t i = 0; i < after.size(); ++i) {
      const CloudPoint q = after.point(i);
      if (!Finite(q)) continue;
      const Eigen::Vector3f position = motion * Position(q);
      if ((position.array() < lo.array()).any() || (position.array() > hi.array()).any()) {
        continue;
      }
      cells_[GridCellKey(position.x(), position.y(), position.z(), inverse_)].push_back(position);
    }
  }

  bool AnyWithin(const Eigen::Vector3f& p, float radius) const {
    const float squared = radius * radius;
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = cells_.find(GridCellKey(
              p.x() + static_cast<float>(dx) * cell_, p.y() + static_cast<float>(dy) * cell_,
              p.z() + static_cast<float>(dz) * cell_, inverse_));
          if (it == cells_.end()) continue;
          for (const Eigen::Vector3f& q : it->second) {
            if ((q - p).squaredNorm() <= squared) return true;
          }
        }
      }
    }
    return false;
  }

 private:
  float inverse_, cell_;
  std::unordered_map<std::uint64_t, std::vector<Eigen::Vector3f>> cells_;
};

// The object's points looked up besides the target's, at most (an even sample): a share
// needs no more.
constexpr std::size_t kObjectSamples = 2000;

// What the after frame shows of a set of before-points.
struct SeenCounts {
  std::size_t points = 0, supported = 0, vacated = 0, occluded = 0;
  // Vacated points with nothing within min_motion of them either (all vacated ones when
  // min_motion is under the noise's tolerance).
  std::size_t vacated_beyond = 0;

  void Add(Seen seen, bool beyond) {
    supported += seen == Seen::kSupported;
    vacated += seen == Seen::kVacated;
    occluded += seen == Seen::kOccluded;
    vacated_beyond += seen == Seen::kVacated && beyond;
  }
  // A set the after frame mostly does not show (holes, the image border after the camera
  // moved) is not judged: half of it at least must be seen, occluded points included. The
  // share of vacated points is of those whose pixel still says something about the set's own
  // surface (still there or seen through): an occluded point only says that something is in
  // front now, the object itself pushed towards the camera as often as a neighbour knocked in
  // front of one that stayed, so it counts neither way. And a few points seen through are not
  // enough: a camera that moved reveals a strip behind every edge (8 of 53 points of a
  // supervoxel of kinect_static_seq_1 -> 2).
  // The share is judged by the camera's noise alone; the smallest motion that counts only
  // asks that min_points of the vacated points moved farther than it.
  bool Moved(double min_fraction, std::size_t min_points) const {
    const std::size_t shown = supported + vacated + occluded;
    return 2 * shown >= points && vacated >= min_points && vacated_beyond >= min_points &&
           static_cast<double>(vacated) >= min_fraction * static_cast<double>(supported + vacated);
  }
};

// The finite points of `s`, by index into `before`.
void AppendFinitePoints(const Cloud& before, const Supervoxel& s,
                        std::vector<std::pair<std::size_t, CloudPoint>>& points) {
  for (const std::int32_t i : s.point_indices) {
    const CloudPoint p = before.point(static_cast<std::size_t>(i));
    if (Finite(p)) points.emplace_back(static_cast<std::size_t>(i), p);
  }
}

}  // namespace

void DetectByVisibility(const Cloud& before, const Cloud& after, const Supervoxel& target,
                        const std::vector<const Supervoxel*>& object,
                        const ChangeDetectorConfig& config, ChangeEvidence& e) {
  // The target's points first, then the rest of its object's: every `stride`-th of those, at
  // most kObjectSamples, so that an object that is a whole table (its flood reaches
  // what stands on it through a smooth straddling supervoxel) costs no more than a brick. The
  // object's counts are the sampled ones times the stride.
  std::vector<std::pair<std::size_t, CloudPoint>> points;
  AppendFinitePoints(before, target, points);
  const std::size_t target_count = points.size();
  std::vector<std::pair<std::size_t, CloudPoint>> rest;
  for (const Supervoxel* s : object) AppendFinitePoints(before, *s, rest);
  const std::size_t stride = (rest.size() + kObjectSamples - 1) / kObjectSamples;
  for (std::size_t k = 0; k < rest.size(); k += std::max<std::size_t>(1, stride)) {
    points.push_back(rest[k]);
  }
  e.target_points = target_count;
  e.object_supervoxels = 1 + object.size();
  e.object_points = target_count + rest.size();
  if (target_count == 0) return;
  std::vector<Seen> seen_of(points.size(), Seen::kUnknown);
  // Whether a vacated point has no after-point within min_motion either.
  std::vector<bool> beyond_motion(points.size(), true);

  const std::optional<Intrinsics> intrinsics = IntrinsicsOf(before);
  std::optional<CameraMotion> estimate;
  if (config.compensate_camera_motion) {
    estimate = EstimateCameraMotion(before, intrinsics, after,
                                    static_cast<std::size_t>(config.motion_samples),
                                    config.motion_max_distance);
    if (!estimate->converged) estimate.reset();
  }
  Eigen::Isometry3f motion = Eigen::Isometry3f::Identity();
  if (intrinsics) {
    std::vector<SeenPoint> seen =
        ReprojectInto(after, motion, *intrinsics, before.width(), before.height());
    // The camera moved only if the frames agree better with the motion than without it: on
    // a still camera, the registration fits the sensor's noise and quantisation (0.1-0.3
    // degrees on the simulated Kinect), which would move every surface by a few mm.
    if (estimate) {
      std::vector<SeenPoint> moved = ReprojectInto(after, estimate->before_from_after, *intrinsics,
                                                   before.width(), before.height());
      if (SupportedShare(before, moved, config) > SupportedShare(before, seen, config)) {
        seen = std::move(moved);
        motion = estimate->before_from_after;
        e.camera_rotation_deg = estimate->rotation_deg;
        e.camera_translation_m = estimate->translation_m;
      }
    }
    // Only the colour check needs the gain.
    const Eigen::Array3d gain =
        config.colour_tolerance > 0 ? ColourGain(before, seen, config) : Eigen::Array3d::Ones();
    for (std::size_t k = 0; k < points.size(); ++k) {
      const auto& [index, p] = points[k];
      const Reach noise = NoiseReach(config, p.z);
      seen_of[k] = SeenAlongRay(seen, before.width(), before.height(), index, p, noise.distance,
                                noise.window, gain, config.colour_tolerance);
      // Only vacated points are searched again, over the wider window a motion too small to
      // count needs.
      if (seen_of[k] != Seen::kVacated || config.min_motion <= noise.distance) continue;
      const Reach wider = MotionReach(config, intrinsics->fx, p.z);
      beyond_motion[k] = SeenAlongRay(seen, before.width(), before.height(), index, p,
                                      wider.distance, std::max(noise.window, wider.window), gain,
                                      config.colour_tolerance) != Seen::kSupported;
    }
  } else {
    Eigen::Vector3f lo = Position(points.front().second), hi = lo;
    float cell = 0;
    for (const auto& [index, p] : points) {
      lo = lo.cwiseMin(Position(p));
      hi = hi.cwiseMax(Position(p));
      cell =
          std::max(cell, static_cast<float>(std::max(Tolerance(config, p.z), config.min_motion)));
    }
    if (estimate) {
      motion = estimate->before_from_after;
      e.camera_rotation_deg = estimate->rotation_deg;
      e.camera_translation_m = estimate->translation_m;
    }
    const NearbyAfterPoints nearby(after, motion, lo.array() - cell, hi.array() + cell, cell);
    for (std::size_t k = 0; k < points.size(); ++k) {
      const auto& [index, p] = points[k];
      const double tolerance = Tolerance(config, p.z);
      seen_of[k] = nearby.AnyWithin(Position(p), static_cast<float>(tolerance)) ? Seen::kSupported
                                                                                : Seen::kVacated;
      beyond_motion[k] = config.min_motion <= tolerance ||
                         !nearby.AnyWithin(Position(p), static_cast<float>(config.min_motion));
    }
  }
  SeenCounts of_target, of_rest;
  of_target.points = target_count;
  of_rest.points = points.size() - target_count;
  for (std::size_t k = 0; k < points.size(); ++k) {
    (k < target_count ? of_target : of_rest).Add(seen_of[k], beyond_motion[k]);
  }
  const std::size_t weight = std::max<std::size_t>(1, stride);
  SeenCounts of_object;
  of_object.points = target_count + rest.size();
  of_object.supported = of_target.supported + weight * of_rest.supported;
  of_object.vacated = of_target.vacated + weight * of_rest.vacated;
  of_object.occluded = of_target.occluded + weight * of_rest.occluded;
  of_object.vacated_beyond = of_target.vacated_beyond + weight * of_rest.vacated_beyond;
  e.supported_points = of_target.supported;
  e.vacated_points = of_target.vacated;
  e.occluded_points = of_target.occluded;
  e.object_supported_points = of_object.supported;
  e.object_vacated_points = of_object.vacated;
  e.object_occluded_points = of_object.occluded;
  e.vacated_beyond_motion_points = of_target.vacated_beyond;
  e.object_vacated_beyond_motion_points = of_object.vacated_beyond;
  // A push moves an object, not a supervoxel: the target moved with its object when the
  // object shows the vacated share of a move (a brick slid along its own top: its top's
  // pixels see the same surface, its trailing faces are seen through; a small object whose
  // target supervoxel alone has too few points to count).
  const auto min_points = static_cast<std::size_t>(config.min_vacated_points);
  e.moved = of_target.Moved(config.min_vacated_fraction, min_points) ||
            of_object.Moved(config.min_vacated_fraction, min_points);
}

}  // namespace relmap::perception
