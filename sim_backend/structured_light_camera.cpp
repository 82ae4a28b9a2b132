// RenderStructuredLight: an exact ray-cast pass (depth, incidence, projector
// shadow), then the sensor's failures and noise drawn per pixel.
#include "structured_light_camera.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <thread>
#include <vector>

#include "common/random.h"
#include "kinect_noise_model.h"
#include "ray_casting.h"

namespace relmap::sim {
namespace {

// Rays are cast a little past max_range so that depths rounded down into range
// still have a surface behind them.
constexpr double kCastMargin = 1.1;
// A shadow ray stops this short of its hit point (metres), so that the surface
// itself never counts as the occluder.
constexpr double kShadowTolerance = 1e-3;

// A pixel's draws, each from its own slot: the noise of a pixel depends on the
// frame's seed, the pixel and the slot only, never on the order pixels are
// rendered in (SplitMix64's outputs, indexed). A pair of Gaussians takes two
// slots; both of Box-Muller's outputs are used, as the transcendental functions
// are most of the model's cost.
enum Slot : std::uint64_t {
  kLateral = 0,      // the shifts along u and v
  kAxialAndRed = 2,  // the disparity noise and the red channel's
  kGreenBlue = 4,
  kEdge = 6,
  kSlotsPerPixel = 8,
};

class PixelDraws {
 public:
  PixelDraws(std::uint64_t frame_seed, std::size_t pixel)
      : base_(frame_seed + pixel * kSlotsPerPixel * kSplitMix64Gamma) {}
  double Uniform01(std::uint64_t slot) const {
    return UnitFromBits(SplitMix64At(base_ + slot * kSplitMix64Gamma));
  }
  // Two independent standard normals from slots `slot` and `slot + 1` (Box-Muller).
  Eigen::Vector2d Gaussians(std::uint64_t slot) const {
    const double u1 = 1.0 - Uniform01(slot);  // (0, 1]: log is finite
    const double radius = std::sqrt(-2.0 * std::log(u1));
    const double angle = 2 * std::numbers::pi * Uniform01(slot + 1);
    return {radius * std::cos(angle), radius * std::sin(angle)};
  }

 private:
  std::uint64_t base_;
};

// What the ray through a pixel's centre meets, exactly.
struct Sample {
  double z = 0;      // depth along the optical axis, metres; 0: nothing met
  double theta = 0;  // incidence: the angle between the surface normal and the ray
  std::int32_t body = kNoBody;
  bool measurable = false;                        // met, lit by the projector, not too oblique
  Eigen::Vector3d rgb = Eigen::Vector3d::Zero();  // shaded, in [0, 1]
};

// Whether the projector at `projector` lights `hit_world` on a surface whose
// normal (facing the camera) is `normal`: the surface faces it and nothing
// nearer lies on the segment between them.
bool Lit(dGeomID ray, const std::vector<Candidate>& candidates, const Eigen::Vector3d& projector,
         const Eigen::Vector3d& hit_world, const Eigen::Vector3d& normal) {
  const Eigen::Vector3d to_hit = hit_world - projector;
  if (normal.dot(-to_hit) <= 0) return false;
  const double length = to_hit.norm();
  return !Blocked(ray, candidates, projector, to_hit / length, length - kShadowTolerance);
}

// Runs `rows(first, step)` on the rows first, first + step, ... of a frame: on
// two threads (rows 0, 2, 4, ... and 1, 3, 5, ...) when `two_threads`. Every
// pixel's result depends on that pixel alone, so the split changes nothing.
template <typename Rows>
void ForRows(bool two_threads, const Rows& rows) {
  if (!two_threads) {
    rows(0, 1);
    return;
  }
  std::thread odd([&] { rows(1, 2); });
  rows(0, 2);
  odd.join();
}

// Fills the rows first, first + step, ... of `samples` with `ray`. ODE's
// ray-primitive colliders only read the geoms, whose poses and boxes
// CandidatesOf has brought up to date, so two rays may collide at once.
void CastRows(const CameraModel& camera, const LightSettings& light,
              const std::vector<Candidate>& candidates, dGeomID ray, std::uint32_t first,
              std::uint32_t step, std::vector<Sample>& samples) {
  const Eigen::Matrix3d world_from_camera = camera.world_from_camera.linear();
  const Eigen::Vector3d origin = camera.world_from_camera.translation();
  const Eigen::Vector3d projector =
      camera.world_from_camera * Eigen::Vector3d(camera.noise.baseline, 0, 0);
  std::vector<Entry> entries;
  for (std::uint32_t v = first; v < camera.height; v += step) {
    for (std::uint32_t u = 0; u < camera.width; ++u) {
      const Eigen::Vector3d ray_camera =
          Eigen::Vector3d((u - camera.cx) / camera.fx, (v - camera.cy) / camera.fy, 1.0)
              .normalized();
      const Eigen::Vector3d ray_world = world_from_camera * ray_camera;
      const std::optional<RayHit> hit =
          Nearest(ray, candidates, origin, ray_world,
                  kCastMargin * camera.max_range / ray_camera.z(), entries);
      if (!hit) continue;
      Sample& s = samples[static_cast<std::size_t>(v) * camera.width + u];
      const Eigen::Vector3d hit_world = origin + hit->distance * ray_world;
      s.z = hit->distance * ray_camera.z();
      s.theta = std::acos(std::clamp(-hit->normal.dot(ray_world), 0.0, 1.0));
      s.body = TagOf(hit->geom).body_id;
      s.rgb = ShadedColour(*hit, hit_world, light);
      // Shadow rays only where the sensor could measure at all.
      s.measurable = s.theta <= camera.structured_light.max_incidence &&
                     Lit(ray, candidates, projector, hit_world, hit->normal);
    }
  }
}

// Per pixel, whether its 3x3 neighbourhood holds a disparity jump: the block
// matcher's window straddles an edge there. Nothing met counts as disparity 0.
std::vector<char> DepthEdges(const CameraModel& camera, const std::vector<Sample>& samples) {
  const int w = static_cast<int>(camera.width), h = static_cast<int>(camera.height);
  // Neighbours are reference_width / width native pixels apart.
  const double jump = camera.structured_light.edge_disparity_jump_px *
                      camera.noise.reference_width_px / camera.width;
  std::vector<double> disparity(samples.size(), 0.0);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (samples[i].z > 0) disparity[i] = DisparityOf(camera.noise, samples[i].z);
  }
  std::vector<char> edges(samples.size(), 0);
  for (int v = 0; v < h; ++v) {
    for (int u = 0; u < w; ++u) {
      const double d = disparity[static_cast<std::size_t>(v) * w + u];
      for (int dv = -1; dv <= 1 && !edges[v * w + u]; ++dv) {
        for (int du = -1; du <= 1; ++du) {
          const int nu = u + du, nv = v + dv;
          if (nu < 0 || nv < 0 || nu >= w || nv >= h) continue;
          if (std::abs(disparity[static_cast<std::size_t>(nv) * w + nu] - d) > jump) {
            edges[static_cast<std::size_t>(v) * w + u] = 1;
            break;
          }
        }
      }
    }
  }
  return edges;
}

int Jittered(int at, double shift, int size) {
  return std::clamp(static_cast<int>(std::lround(at + shift)), 0, size - 1);
}

// The frame's pixels on the rows first, first + step, ...: each pixel's colour
// from its own sample, its depth from a laterally jittered one, through the
// sensor's failures and noise.
struct PixelPass {
  const CameraModel& camera;
  const std::vector<Sample>& samples;
  const std::vector<char>& edges;
  std::uint64_t frame_seed;
  Eigen::Vector3d gain;  // exposure times white balance, times 255
  CameraFrame& frame;

  void operator()(int first, int step) const {
    const KinectNoiseModel& model = camera.noise;
    const StructuredLightSettings& sensor = camera.structured_light;
    constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
    const int w = static_cast<int>(camera.width), h = static_cast<int>(camera.height);
    for (int v = first; v < h; v += step) {
      for (int u = 0; u < w; ++u) {
        const std::size_t index = static_cast<std::size_t>(v) * w + u;
        const PixelDraws draws(frame_seed, index);
        const Sample& own = samples[index];
        CameraPoint& point = frame.points[index];
        point.x = point.y = point.z = kNan;
        const Eigen::Vector2d axial_red = draws.Gaussians(kAxialAndRed);
        // The colour camera sees what the pixel's ray meets, depth or not.
        if (own.z > 0) {
          const Eigen::Vector2d green_blue = draws.Gaussians(kGreenBlue);
          const Eigen::Vector3d rgb =
              own.rgb.cwiseProduct(gain) +
              sensor.color_noise_sigma *
                  Eigen::Vector3d(axial_red[1], green_blue[0], green_blue[1]);
          point.r = ToByte(rgb.x() / 255.0);
          point.g = ToByte(rgb.y() / 255.0);
          point.b = ToByte(rgb.z() / 255.0);
        }
        // Lateral noise (Nguyen et al.): the depth comes from a jittered position.
        const double sigma_l = LateralSigmaPixels(model, own.theta, camera.width);
        const Eigen::Vector2d shift = sigma_l * draws.Gaussians(kLateral);
        const std::size_t source =
            static_cast<std::size_t>(Jittered(v, shift[1], h)) * w + Jittered(u, shift[0], w);
        const Sample& s = samples[source];
        if (!s.measurable) continue;
        if (edges[source] && draws.Uniform01(kEdge) < sensor.edge_hole_probability) continue;
        // Axial noise in the disparity domain, then the sensor's 1/8 px steps.
        const double disparity = QuantisedDisparity(
            model, DisparityOf(model, s.z) + DisparitySigma(model, s.z, s.theta) * axial_red[0]);
        if (disparity <= 0) continue;
        const double z = DepthOf(model, disparity);
        if (z < camera.min_range || z > camera.max_range) continue;
        // The sensor reports z: the point lies on the pixel's own ray.
        point.x = static_cast<float>((u - camera.cx) / camera.fx * z);
        point.y = static_cast<float>((v - camera.cy) / camera.fy * z);
        point.z = static_cast<float>(z);
        frame.body_ids[index] = s.body;
      }
    }
  }
};

}  // namespace

CameraFrame RenderStructuredLight(const CameraModel& camera, const LightSettings& light,
                                  OdeWorld& world, const std::array<dGeomID, 2>& rays,
                                  SeededRandom& noise) {
  const StructuredLightSettings& sensor = camera.structured_light;
  const std::uint64_t frame_seed = noise.Below(~std::uint64_t{0});
  // Auto exposure and white balance drift from frame to frame.
  const double exposure = std::max(0.0, 1.0 + sensor.exposure_sigma * noise.Gaussian());
  Eigen::Vector3d gain;
  for (int c = 0; c < 3; ++c) {
    gain[c] = 255.0 * exposure * std::max(0.0, 1.0 + sensor.white_balance_sigma * noise.Gaussian());
  }

  const bool two_threads = !world.has_meshes();
  const std::vector<Candidate> candidates = CandidatesOf(world, /*static_only=*/false);
  std::vector<Sample> samples(static_cast<std::size_t>(camera.width) * camera.height);
  ForRows(two_threads, [&](std::uint32_t first, std::uint32_t step) {
    CastRows(camera, light, candidates, rays[first], first, step, samples);
  });
  const std::vector<char> edges = DepthEdges(camera, samples);

  CameraFrame frame;
  frame.width = camera.width;
  frame.height = camera.height;
  frame.points.assign(samples.size(), CameraPoint{});
  frame.body_ids.assign(samples.size(), kNoBody);
  const PixelPass pixels{camera, samples, edges, frame_seed, gain, frame};
  ForRows(two_threads, [&](int first, int step) { pixels(first, step); });
  return frame;
}

}  // namespace relmap::sim
