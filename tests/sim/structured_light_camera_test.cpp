// The kinect_v1 sensor against its model: depth noise statistics on flat walls,
// disparity steps, and the holes of a structured-light camera (projector shadow,
// depth edges, grazing angles, range), colour noise, and seeding.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <set>

#include "frame_pixels.h"
#include "kinect_noise_model.h"
#include "world_test_scenes.h"

namespace relmap::sim {
namespace {

using testing::LoadOrDie;

// A Kinect at the world origin looking along +x at 320 x 240 (fx = fy = 262.5,
// centre (159.5, 119.5)): its x is world -y, so the IR projector, 7.5 cm along
// camera +x, sits at world (0, -0.075, 0). `sensor_noise` overrides the model.
std::string Camera(const std::string& sensor_noise = "{}") {
  return R"("camera": {"position": {}, "look_at": {"x": 1}, "sensor_noise": )" + sensor_noise + "}";
}

// Static boxes (each "size", "pose" and colour) and an object out of sight.
std::string Scene(const std::string& camera, const std::string& static_bodies) {
  return R"({"name": "Kinect", )" + camera + R"(, "static_bodies": [)" + static_bodies + R"(],
    "objects": [{"shape": "sphere", "radius": 0.01, "color": {"b": 255}, "mass": 0.1,
      "spawn": {"min": {"x": -5}, "max": {"x": -5}}}],
    "physics": {"gravity": 0}})";
}

// A wall whose face, facing the camera, is the plane x = `face_x`, rotated by
// `yaw_deg` about the vertical through that face's centre.
std::string Wall(double face_x, double yaw_deg = 0) {
  const double c = std::cos(yaw_deg * M_PI / 180), s = std::sin(yaw_deg * M_PI / 180);
  // The box's centre sits 0.05 behind its face, along the rotated x axis.
  return R"({"shape": "box", "size": {"x": 0.1, "y": 8, "z": 8}, "color": {"g": 200},
    "pose": {"position": {"x": )" +
         std::to_string(face_x + 0.05 * c) + R"(, "y": )" + std::to_string(0.05 * s) +
         R"(}, "rpy_deg": {"z": )" + std::to_string(yaw_deg) + "}}}";
}

// A box whose front face is the plane x = 1, |y| <= 0.19, |z| <= 0.2.
constexpr char kBox[] = R"({"shape": "box", "size": {"x": 0.2, "y": 0.38, "z": 0.4},
    "color": {"r": 200}, "pose": {"position": {"x": 1.1}}})";

bool Hole(const CameraFrame& frame, int u, int v) {
  return std::isnan(At(frame, u, v).z) && IdAt(frame, u, v) == kNoBody;
}

// Every field of every pixel, coordinates by their bits (NaNs included; not the
// struct's padding).
bool Identical(const CameraFrame& a, const CameraFrame& b) {
  if (a.points.size() != b.points.size() || a.body_ids != b.body_ids) return false;
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    const CameraPoint &p = a.points[i], &q = b.points[i];
    const float pf[3] = {p.x, p.y, p.z}, qf[3] = {q.x, q.y, q.z};
    // Bit for bit, NaN holes included: that is what deterministic means here.
    if (std::memcmp(pf, qf, sizeof pf) != 0 ||  // NOLINT(bugprone-suspicious-memory-comparison)
        p.r != q.r || p.g != q.g || p.b != q.b) {
      return false;
    }
  }
  return true;
}

class FlatWall : public ::testing::TestWithParam<double> {};

// Over two frames of a wall at depth z filling the view: the mean error is
// within a tenth of a step plus five standard errors, and the standard deviation
// is the model's σz (pooled over the pixels' incidence angles) within five
// standard errors (σ / sqrt(2N)) plus 3 % for the rounding's dependence on where
// z falls between two steps (Sheppard's correction is exact only on average).
TEST_P(FlatWall, DepthErrorsHaveTheModelsMeanAndSpread) {
  const double z = GetParam();
  auto scene = LoadOrDie(Scene(Camera(), Wall(z)), 11);
  const CameraModel& camera = scene->camera();
  double sum = 0, sum_sq = 0, expected_variance = 0;
  std::size_t n = 0;
  for (int frame_index = 0; frame_index < 2; ++frame_index) {
    const CameraFrame frame = scene->Capture();
    for (int v = 0; v < static_cast<int>(frame.height); ++v) {
      for (int u = 0; u < static_cast<int>(frame.width); ++u) {
        const CameraPoint& p = At(frame, u, v);
        if (std::isnan(p.z)) continue;
        // The ray through (u, v) meets the wall at an angle θ with cos θ = its z.
        const double cos_theta =
            Eigen::Vector3d((u - camera.cx) / camera.fx, (v - camera.cy) / camera.fy, 1)
                .normalized()
                .z();
        const double sigma = AxialSigma(camera.noise, z, std::acos(cos_theta));
        expected_variance += sigma * sigma;
        sum += p.z - z;
        sum_sq += (p.z - z) * (p.z - z);
        ++n;
      }
    }
  }
  ASSERT_GT(n, 2u * 320 * 240 * 99 / 100);  // a plain wall in range has (almost) no holes
  const auto count = static_cast<double>(n);
  const double mean = sum / count;
  const double sigma = std::sqrt(sum_sq / count - mean * mean);
  const double expected = std::sqrt(expected_variance / count);
  EXPECT_LT(std::abs(mean),
            0.1 * QuantisationStep(camera.noise, z) + 5 * expected / std::sqrt(count))
      << z;
  EXPECT_NEAR(sigma, expected, 0.03 * expected + 5 * expected / std::sqrt(2.0 * count)) << z;
}

// Every reported depth is f b / (k / 8) for an integer k, and the distinct depths
// are neighbouring steps: at least three of them, one step z²/(8 f b) apart.
TEST_P(FlatWall, DepthsComeInDisparitySteps) {
  const double z = GetParam();
  auto scene = LoadOrDie(Scene(Camera(), Wall(z)), 12);
  const KinectNoiseModel& model = scene->camera().noise;
  std::set<long> steps;
  for (const CameraPoint& p : scene->Capture().points) {
    if (std::isnan(p.z)) continue;
    const double k = DisparityOf(model, p.z) * model.disparity_steps_per_px;
    ASSERT_NEAR(k, std::round(k), 1e-3) << p.z;
    steps.insert(std::lround(k));
  }
  ASSERT_GE(steps.size(), 3u) << z;
  EXPECT_LE(*steps.rbegin() - *steps.begin() + 1, static_cast<long>(steps.size()) + 2);
  // Two neighbouring steps around z are QuantisationStep(z) apart (to first order).
  const long k = std::lround(DisparityOf(model, z) * model.disparity_steps_per_px);
  const double gap = model.ir_focal_px * model.baseline * model.disparity_steps_per_px *
                     (1.0 / static_cast<double>(k) - 1.0 / static_cast<double>(k + 1));
  EXPECT_NEAR(gap, QuantisationStep(model, z), 0.02 * QuantisationStep(model, z));
}

INSTANTIATE_TEST_SUITE_P(Depths, FlatWall, ::testing::Values(0.6, 1.0, 1.5, 2.5));

// Without lateral noise or edge dropouts, so that only the shadow makes holes.
constexpr char kShadowOnly[] =
    R"({"lateral_constant_px": 0, "lateral_grazing_px": 0, "edge_hole_probability": 0})";

TEST(StructuredLight, TheProjectorsShadowIsABandBesideTheBoxOnItsSide) {
  // The wall at x = 2 behind the box. From the camera the box's +y edge hides the
  // wall up to y = 0.19 * 2 = 0.38; from the projector at y = -0.075 it shadows
  // it up to y = -0.075 + (0.19 + 0.075) * 2 = 0.455. The camera sees that band,
  // camera x in (-0.455, -0.38) at depth 2: u in (159.5 - 59.7, 159.5 - 49.9) =
  // (99.8, 109.6), left of the box (image left is world +y). On the other side the
  // shadow lies behind the box.
  auto scene = LoadOrDie(Scene(Camera(kShadowOnly), std::string(kBox) + "," + Wall(2.0)));
  const CameraFrame frame = scene->Capture();
  for (int v = 90; v <= 150; ++v) {
    for (int u = 0; u < 320; ++u) {
      const bool in_band = u >= 100 && u <= 109;
      EXPECT_EQ(Hole(frame, u, v), in_band) << u << "," << v;
    }
  }
}

TEST(StructuredLight, ShadowsMoveToTheOtherSideWithTheProjector) {
  // With the projector on camera -x (a negative baseline is not allowed, so
  // the camera is turned upside down instead): the band is right of the box.
  auto scene = LoadOrDie(Scene(R"("camera": {"position": {}, "look_at": {"x": 1},
      "up": {"z": -1}, "sensor_noise": )" +
                                   std::string(kShadowOnly) + "}",
                               std::string(kBox) + "," + Wall(2.0)));
  const CameraFrame frame = scene->Capture();
  for (int u = 0; u < 320; ++u) {
    EXPECT_EQ(Hole(frame, u, 120), u >= 100 && u <= 109) << u;
  }
}

TEST(StructuredLight, DepthEdgesDropOutInAOnePixelBandEachSide) {
  // The box's -y edge is at camera x = 0.19: u = 159.5 + 262.5 * 0.19 = 209.4, so
  // column 209 sees the box (z = 1) and column 210 the wall (z = 2): a disparity
  // jump of 43.5 - 21.75 px, far above 1 px per native pixel (2 at 320 wide).
  const std::string scene_text = R"({"lateral_constant_px": 0, "lateral_grazing_px": 0,
      "edge_hole_probability": )";
  auto always = LoadOrDie(Scene(Camera(scene_text + "1}"), std::string(kBox) + "," + Wall(2.0)));
  auto never = LoadOrDie(Scene(Camera(scene_text + "0}"), std::string(kBox) + "," + Wall(2.0)));
  const CameraFrame a = always->Capture(), b = never->Capture();
  for (int v = 100; v <= 140; ++v) {
    for (int u = 200; u <= 220; ++u) {
      EXPECT_EQ(Hole(a, u, v), u == 209 || u == 210) << u << "," << v;
      EXPECT_FALSE(Hole(b, u, v)) << u << "," << v;
    }
  }
}

TEST(StructuredLight, GrazingSurfacesAreHoles) {
  // A wall through (1.5, 0, 0) turned by 80° meets the central rays at ~80°, past
  // the 75° limit; turned by 70° it is measured.
  auto steep = LoadOrDie(Scene(Camera(), Wall(1.5, 80)));
  auto oblique = LoadOrDie(Scene(Camera(), Wall(1.5, 70)));
  const CameraFrame s = steep->Capture(), o = oblique->Capture();
  int steep_holes = 0, oblique_holes = 0;
  for (int v = 115; v <= 125; ++v) {
    for (int u = 155; u <= 165; ++u) {
      steep_holes += Hole(s, u, v);
      oblique_holes += Hole(o, u, v);
    }
  }
  EXPECT_EQ(steep_holes, 121);
  EXPECT_EQ(oblique_holes, 0);
}

TEST(StructuredLight, DepthsOutsideTheWorkingRangeAreHoles) {
  // Defaults 0.5 to 4.0 m on z; a file may narrow them.
  for (const auto& [camera, face_x, holes] :
       {std::tuple{Camera(), 0.45, true},
        {Camera(), 4.5, true},
        {Camera(), 3.5, false},
        {std::string(R"("camera": {"position": {}, "look_at": {"x": 1}, "max_range": 2})"), 2.5,
         true}}) {
    auto scene = LoadOrDie(Scene(camera, Wall(face_x)));
    int hole_count = 0;
    const CameraFrame frame = scene->Capture();
    for (int v = 0; v < 240; ++v) {
      for (int u = 0; u < 320; ++u) hole_count += Hole(frame, u, v);
    }
    if (holes) {
      EXPECT_EQ(hole_count, 320 * 240) << face_x;
    } else {
      EXPECT_LT(hole_count, 320 * 240 / 100) << face_x;
    }
  }
}

TEST(StructuredLight, ColourNoiseHasTheConfiguredSpread) {
  // A plain wall shades to one colour; with exposure and white balance fixed, the
  // green channel varies by the 2-level noise plus rounding's 1/12 level².
  auto scene = LoadOrDie(
      Scene(Camera(R"({"exposure_sigma": 0, "white_balance_sigma": 0, "color_noise_sigma": 2})"),
            Wall(1.5)));
  double sum = 0, sum_sq = 0;
  const CameraFrame frame = scene->Capture();
  for (const CameraPoint& p : frame.points) {
    sum += p.g;
    sum_sq += double(p.g) * p.g;
  }
  const auto n = static_cast<double>(frame.points.size());
  const double mean = sum / n;
  EXPECT_NEAR(std::sqrt(sum_sq / n - mean * mean), std::sqrt(4.0 + 1.0 / 12), 0.05);
}

TEST(StructuredLight, ExposureChangesFromFrameToFrame) {
  auto scene = LoadOrDie(Scene(Camera(), Wall(1.5)));
  const auto mean_green = [](const CameraFrame& frame) {
    double sum = 0;
    for (const CameraPoint& p : frame.points) sum += p.g;
    return sum / static_cast<double>(frame.points.size());
  };
  const double first = mean_green(scene->Capture()), second = mean_green(scene->Capture());
  EXPECT_NE(first, second);
  EXPECT_NEAR(first / second, 1.0, 0.25);  // a few per cent, not a different scene
}

TEST(StructuredLight, TheSameSeedGivesBitIdenticalFramesAndAnotherSeedOthers) {
  const std::string text = Scene(Camera(), std::string(kBox) + "," + Wall(2.0));
  auto a = LoadOrDie(text, 5);
  auto b = LoadOrDie(text, 5);
  auto c = LoadOrDie(text, 6);
  const CameraFrame fa = a->Capture(), fb = b->Capture(), fc = c->Capture();
  EXPECT_TRUE(Identical(fa, fb));
  EXPECT_FALSE(Identical(fa, fc));
  EXPECT_FALSE(Identical(fa, a->Capture()));  // the next frame draws anew
  EXPECT_FALSE(Identical(b->Capture(), c->Capture()));
}

TEST(StructuredLight, TwoThreadsRenderWhatOneThreadRenders) {
  // A triangle mesh keeps the renderer on one thread (Debian's ODE shares one
  // mesh collision cache); this one lies behind the camera, where no ray goes,
  // and comes last among the static bodies, so every id in sight is unchanged.
  const std::string bodies = std::string(kBox) + "," + Wall(2.0);
  const std::string mesh = R"({"shape": "mesh", "color": {"r": 9}, "mesh": {
      "vertices": [-3, 0, 0, -3, 1, 0, -3, 0, 1], "indices": [0, 1, 2]}})";
  auto threaded = LoadOrDie(Scene(Camera(), bodies), 8);
  auto serial = LoadOrDie(Scene(Camera(), bodies + "," + mesh), 8);
  for (int frame = 0; frame < 2; ++frame) {
    EXPECT_TRUE(Identical(threaded->Capture(), serial->Capture())) << frame;
  }
}

}  // namespace
}  // namespace relmap::sim
