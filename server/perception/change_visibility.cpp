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
#include "perception/object_motion.h"
#include "perception/perception_config.h"

namespace relmap::perception {
namespace {

Eigen::Vector3f Position(const CloudPoint& p) { return {p.x, p.y, p.z}; }

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
    if (!pcd::HasPosition(p) || !q.allFinite()) continue;
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
    if (!pcd::HasPosition(p)) continue;
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
      if (!pcd::HasPosition(q)) continue;
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

// A point looked up: its index into `before`, the point, and the part of the object it is
// on (0 the target, k the object's k-th other supervoxel).
struct ObjectPoint {
  std::size_t index;
  CloudPoint point;
  std::size_t part;
};

// The finite points of `s`, part `part` of the object.
void AppendFinitePoints(const Cloud& before, const Supervoxel& s, std::size_t part,
                        std::vector<ObjectPoint>& points) {
  for (const std::int32_t i : s.point_indices) {
    const CloudPoint p = before.point(static_cast<std::size_t>(i));
    if (pcd::HasPosition(p)) points.push_back({static_cast<std::size_t>(i), p, part});
  }
}

// How much more often the carried target must be seen through than the target at its own
// place (a z statistic, SeenThroughMore) to say it did not go: three standard errors.
constexpr double kFollowVetoZ = 3.0;
// The largest displacement of an object the rigid check looks for (metres): a push that
// moves an object farther also moves most of what it touches, target included.
constexpr float kObjectMotionReach = 0.05F;
// Neighbours farther apart than this across a pixel's normal (metres) are on two surfaces.
constexpr float kNormalMaxGap = 0.02F;
// Fewer points than this do not pin down a rigid motion against the camera's noise; more
// than kMaxMotionFitPoints (an even sample) add time, not accuracy.
constexpr std::size_t kMinMotionFitPoints = 30;
constexpr std::size_t kMaxMotionFitPoints = 500;

// What the after frame (`seen`, in the before frame's pixels) shows where `motion` takes the
// target's points (points[0, target_count)): still there, seen through or hidden, as for the
// points themselves.
SeenCounts CarriedCounts(const std::vector<ObjectPoint>& points, std::size_t target_count,
                         const Eigen::Isometry3f& motion, const std::vector<SeenPoint>& seen,
                         const Cloud& before, const Intrinsics& k, const Eigen::Array3d& gain,
                         const ChangeDetectorConfig& config) {
  SeenCounts carried;
  carried.points = target_count;
  for (std::size_t i = 0; i < target_count; ++i) {
    const Eigen::Vector3f q = motion * Position(points[i].point);
    const std::optional<Pixel> at = PixelOf(k, q, before.width(), before.height());
    if (!at) continue;
    CloudPoint moved = points[i].point;
    moved.x = q.x(), moved.y = q.y(), moved.z = q.z();
    const std::size_t pixel = static_cast<std::size_t>(at->v) * before.width() + at->u;
    carried.Add(
        SeenAlongRay(seen, before.width(), before.height(), pixel, moved, Tolerance(config, q.z()),
                     config.search_window, gain, config.colour_tolerance),
        true);
  }
  return carried;
}

// Whether a part of the object changed: at least `min_fraction` of what the after frame shows
// of it is seen through or hidden (a face turned towards the camera by the push is hidden
// behind its own new place). With no floor on the count: a part is an even sample.
bool Changed(const SeenCounts& part, double min_fraction) {
  const std::size_t shown = part.supported + part.vacated + part.occluded;
  return shown > 0 && 2 * shown >= part.points &&
         static_cast<double>(part.vacated + part.occluded) >=
             min_fraction * static_cast<double>(shown);
}

// Whether `a` is seen through at a larger share of its points than `b` (of those still
// there or seen through), beyond chance: the one-sided two-proportion z statistic is at
// least `z`. Points of a surface are not independent draws, so the z is a yardstick of
// evidence, not a probability.
bool SeenThroughMore(const SeenCounts& a, const SeenCounts& b, double z) {
  const auto na = static_cast<double>(a.supported + a.vacated);
  const auto nb = static_cast<double>(b.supported + b.vacated);
  if (na == 0 || nb == 0) return false;
  const double pooled = static_cast<double>(a.vacated + b.vacated) / (na + nb);
  const double spread = std::sqrt(pooled * (1 - pooled) * (1 / na + 1 / nb));
  if (!(spread > 0)) return false;
  return (static_cast<double>(a.vacated) / na - static_cast<double>(b.vacated) / nb) / spread >= z;
}

// Whether the target went with its object, when the object shows a move and the target's
// own points do not (a brick slid along its top, the top being the target; or a body flush
// against the pushed one, joined to it by the object's flood): the rigid motion of the
// object's parts that changed, fitted onto the after frame, carries the target's points
// somewhere. The target went with them only if the after frame shows it there as well as
// at its old place: at least half as many of its points still there, and a share seen
// through not larger beyond chance. A face slid along itself is still there at both places,
// and the object's word stands; so it does without a fit (too few points changed, a motion
// that is not rigid or too large).
bool FollowedObject(const std::vector<ObjectPoint>& points, std::size_t target_count,
                    const SeenCounts& of_target, const std::vector<Seen>& seen_of,
                    const std::vector<SeenPoint>& seen, const Cloud& before, const Intrinsics& k,
                    const Eigen::Array3d& gain, const ChangeDetectorConfig& config,
                    ChangeEvidence& e) {
  std::unordered_map<std::size_t, SeenCounts> parts;
  for (std::size_t i = target_count; i < points.size(); ++i) {
    SeenCounts& part = parts[points[i].part];
    ++part.points;
    part.Add(seen_of[i], true);
  }
  std::vector<Eigen::Vector3f> changed;
  Eigen::Vector3f lo = Position(points.front().point), hi = lo;
  float tolerance = 0;
  double depth = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3f p = Position(points[i].point);
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
    tolerance = std::max(tolerance, static_cast<float>(Tolerance(config, p.z())));
    depth += std::fabs(p.z());
    if (i >= target_count && Changed(parts[points[i].part], config.min_vacated_fraction)) {
      changed.push_back(p);
    }
  }
  if (changed.size() < kMinMotionFitPoints) return true;
  // An even sample of the part, and the after frame's surface every `step` pixels, about
  // half the tolerance apart at the object's mean depth: finer adds time, not accuracy.
  std::vector<Eigen::Vector3f> part;
  const std::size_t stride = (changed.size() + kMaxMotionFitPoints - 1) / kMaxMotionFitPoints;
  for (std::size_t i = 0; i < changed.size(); i += stride) part.push_back(changed[i]);
  const double pitch = depth / static_cast<double>(points.size()) / k.fx;
  const auto step = static_cast<std::uint32_t>(std::max(1.0, 0.5 * tolerance / pitch));
  const Eigen::Vector3f margin = Eigen::Vector3f::Constant(kObjectMotionReach);
  const std::vector<SurfacePoint> after = SurfaceWithin(seen, before.width(), before.height(), step,
                                                        lo - margin, hi + margin, kNormalMaxGap);
  const std::optional<ObjectMotion> fit =
      FitObjectMotion(part, after, kObjectMotionReach, tolerance);
  if (!fit) return true;
  e.object_motion_fitted = true;
  Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
  for (const Eigen::Vector3f& p : part) centroid += p;
  centroid /= static_cast<float>(part.size());
  e.object_motion_translation_m = (fit->after_from_before * centroid - centroid).norm();
  e.object_motion_rotation_deg =
      Eigen::AngleAxisf(fit->after_from_before.linear()).angle() * 180.0 / M_PI;
  const SeenCounts carried =
      CarriedCounts(points, target_count, fit->after_from_before, seen, before, k, gain, config);
  e.carried_supported_points = carried.supported;
  e.carried_vacated_points = carried.vacated;
  e.carried_occluded_points = carried.occluded;
  return 2 * carried.supported >= of_target.supported &&
         !SeenThroughMore(carried, of_target, kFollowVetoZ);
}

// The object's other supervoxels that moved by the same test as the target's (SeenCounts::
// Moved), each over its own points among `points` (every `weight`-th of its finite points,
// so the floor on vacated points is scaled down alike). A part the push pushed in front of
// another is hidden, not seen through, and does not count: only what left its place does.
std::vector<std::uint32_t> MovedParts(const std::vector<ObjectPoint>& points,
                                      std::size_t target_count, const std::vector<Seen>& seen_of,
                                      const std::vector<bool>& beyond_motion,
                                      const std::vector<const Supervoxel*>& object,
                                      std::size_t weight, const ChangeDetectorConfig& config) {
  std::vector<SeenCounts> parts(object.size());
  for (std::size_t i = target_count; i < points.size(); ++i) {
    SeenCounts& part = parts[points[i].part - 1];
    ++part.points;
    part.Add(seen_of[i], beyond_motion[i]);
  }
  const std::size_t min_points =
      std::max<std::size_t>(1, static_cast<std::size_t>(config.min_vacated_points) / weight);
  std::vector<std::uint32_t> moved;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    if (parts[k].Moved(config.min_vacated_fraction, min_points)) moved.push_back(object[k]->id);
  }
  std::sort(moved.begin(), moved.end());
  return moved;
}

}  // namespace

void DetectByVisibility(const Cloud& before, const Cloud& after, const Supervoxel& target,
                        const std::vector<const Supervoxel*>& object,
                        const ChangeDetectorConfig& config, ChangeEvidence& e) {
  // The target's points first, then the rest of its object's: every `stride`-th of those, at
  // most kObjectSamples, so that an object that is a whole table (its flood reaches
  // what stands on it through a smooth straddling supervoxel) costs no more than a brick. The
  // object's counts are the sampled ones times the stride.
  std::vector<ObjectPoint> points;
  AppendFinitePoints(before, target, 0, points);
  const std::size_t target_count = points.size();
  std::vector<ObjectPoint> rest;
  for (std::size_t k = 0; k < object.size(); ++k)
    AppendFinitePoints(before, *object[k], k + 1, rest);
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
  // With a pixel grid: the after frame in the before frame's pixels, and the colour gain
  // between them.
  std::vector<SeenPoint> seen;
  Eigen::Array3d gain = Eigen::Array3d::Ones();
  if (intrinsics) {
    seen = ReprojectInto(after, motion, *intrinsics, before.width(), before.height());
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
    if (config.colour_tolerance > 0) gain = ColourGain(before, seen, config);
    for (std::size_t k = 0; k < points.size(); ++k) {
      const auto& [index, p, part] = points[k];
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
    Eigen::Vector3f lo = Position(points.front().point), hi = lo;
    float cell = 0;
    for (const auto& [index, p, part] : points) {
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
      const auto& [index, p, part] = points[k];
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
  // Unless the motion of the object's parts that changed would carry the target where the
  // after frame does not show it (FollowedObject). Without a pixel grid the object's word
  // stands: no ray tells seen through from hidden.
  const auto min_points = static_cast<std::size_t>(config.min_vacated_points);
  if (of_target.Moved(config.min_vacated_fraction, min_points)) {
    e.moved = true;
  } else if (of_object.Moved(config.min_vacated_fraction, min_points)) {
    e.moved = !intrinsics || FollowedObject(points, target_count, of_target, seen_of, seen, before,
                                            *intrinsics, gain, config, e);
  }
  if (e.moved) {
    e.moved_supervoxels =
        MovedParts(points, target_count, seen_of, beyond_motion, object, weight, config);
  }
}

}  // namespace relmap::perception
