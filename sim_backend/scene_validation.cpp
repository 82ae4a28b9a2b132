// ValidateScene: the constraints of scene_schema.proto, with errors that name the
// file and the field path.
#include "scene_validation.h"

#include <charconv>
#include <cmath>
#include <initializer_list>
#include <vector>

#include "scene_settings.h"

namespace relmap::sim {
namespace {

// The largest length accepted anywhere (metres): bigger numbers are typos, and
// ODE's hash space and solver misbehave with them.
constexpr double kMaxLength = 100.0;
constexpr std::uint32_t kMaxCount = 100;
constexpr std::size_t kMaxBodies = 1000;
constexpr std::uint32_t kMaxImageSide = 4096;

// The shortest text that reads back as `value` ("-0.1", not "-0.100000").
std::string Num(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string Index(const std::string& list, std::size_t i) {
  return list + "[" + std::to_string(i) + "]";
}

enum class BodyRole { kStatic, kObject, kPart };

class Checker {
 public:
  explicit Checker(std::string label) : label_(std::move(label)) {}

  void Fail(const std::string& path, const std::string& problem) {
    errors_.push_back(label_ + ": " + path + " " + problem);
  }
  bool Finite(const std::string& path, double v) {
    if (std::isfinite(v)) return true;
    Fail(path, "must be a finite number, got " + Num(v));
    return false;
  }
  void Positive(const std::string& path, double v, double max = kMaxLength) {
    if (!Finite(path, v)) return;
    if (v <= 0) Fail(path, "must be > 0, got " + Num(v));
    if (v > max) Fail(path, "must be <= " + Num(max) + ", got " + Num(v));
  }
  void NonNegative(const std::string& path, double v, double max = kMaxLength) {
    if (!Finite(path, v)) return;
    if (v < 0) Fail(path, "must be >= 0, got " + Num(v));
    if (v > max) Fail(path, "must be <= " + Num(max) + ", got " + Num(v));
  }
  void InRange(const std::string& path, double v, double lo, double hi) {
    if (!Finite(path, v)) return;
    if (v < lo || v > hi) {
      Fail(path, "must be in [" + Num(lo) + ", " + Num(hi) + "], got " + Num(v));
    }
  }
  void FiniteVec(const std::string& path, const Vec3& v, double max = kMaxLength * 10) {
    InRange(path + ".x", v.x(), -max, max);
    InRange(path + ".y", v.y(), -max, max);
    InRange(path + ".z", v.z(), -max, max);
  }
  void PositiveVec(const std::string& path, const Vec3& v) {
    Positive(path + ".x", v.x());
    Positive(path + ".y", v.y());
    Positive(path + ".z", v.z());
  }
  void Colour(const std::string& path, const Rgb& c) {
    for (const auto& [channel, value] : {std::pair{"r", c.r()}, {"g", c.g()}, {"b", c.b()}}) {
      if (value > 255) {
        Fail(path + "." + channel, "must be in [0, 255], got " + std::to_string(value));
      }
    }
  }
  void Missing(const std::string& path, const std::string& why) {
    Fail(path, "is missing (" + why + ")");
  }
  void NotAllowed(const std::string& path, bool present, const std::string& why) {
    if (present) Fail(path, "does not apply " + why);
  }

  Status Result() const {
    if (errors_.empty()) return OkStatus();
    std::string message;
    for (const std::string& e : errors_) message += (message.empty() ? "" : "\n") + e;
    return InvalidArgumentError(message);
  }

 private:
  std::string label_;
  std::vector<std::string> errors_;
};

// Six times the signed volume of a closed mesh with outward triangles (> 0).
double SixSignedVolume(const Mesh& mesh) {
  double six_volume = 0;
  const auto vertex = [&](std::uint32_t i) {
    return Eigen::Vector3d(mesh.vertices(3 * i), mesh.vertices(3 * i + 1),
                           mesh.vertices(3 * i + 2));
  };
  for (int t = 0; t + 2 < mesh.indices_size(); t += 3) {
    six_volume +=
        vertex(mesh.indices(t)).dot(vertex(mesh.indices(t + 1)).cross(vertex(mesh.indices(t + 2))));
  }
  return six_volume;
}

void CheckMesh(Checker& check, const std::string& path, const Mesh& mesh, bool needs_volume) {
  const int value_count = mesh.vertices_size();
  if (value_count < 9 || value_count % 3 != 0) {
    check.Fail(path + ".vertices", "must hold x, y, z triplets of at least 3 vertices, got " +
                                       std::to_string(value_count) + " numbers");
    return;
  }
  for (int i = 0; i < value_count; ++i) {
    check.InRange(Index(path + ".vertices", i), mesh.vertices(i), -kMaxLength, kMaxLength);
  }
  const int index_count = mesh.indices_size();
  if (index_count < 3 || index_count % 3 != 0) {
    check.Fail(path + ".indices", "must hold three vertex indices per triangle, got " +
                                      std::to_string(index_count) + " indices");
    return;
  }
  const auto vertex_count = static_cast<std::uint32_t>(value_count / 3);
  bool indices_ok = true;
  for (int i = 0; i < index_count; ++i) {
    if (mesh.indices(i) >= vertex_count) {
      check.Fail(Index(path + ".indices", i), "must be < " + std::to_string(vertex_count) +
                                                  " (the vertex count), got " +
                                                  std::to_string(mesh.indices(i)));
      indices_ok = false;
    }
  }
  if (!indices_ok) return;
  for (int t = 0; t < index_count; t += 3) {
    const auto v = [&](int k) {
      const std::uint32_t i = mesh.indices(t + k);
      return Eigen::Vector3d(mesh.vertices(3 * i), mesh.vertices(3 * i + 1),
                             mesh.vertices(3 * i + 2));
    };
    if ((v(1) - v(0)).cross(v(2) - v(0)).norm() < 1e-12) {
      check.Fail(path + ".indices", "triangle " + std::to_string(t / 3) + " is degenerate");
    }
  }
  if (needs_volume && !(SixSignedVolume(mesh) > 1e-12)) {
    check.Fail(path,
               "must be closed with outward triangles (counter-clockwise seen from "
               "outside) to give a moveable object a volume; its signed volume is " +
                   Num(SixSignedVolume(mesh) / 6.0));
  }
}

// `moveable`: the body or its composite is an object (a mesh then needs a volume).
void CheckShape(Checker& check, const std::string& path, const Body& body, BodyRole role,
                bool moveable);

void CheckTexture(Checker& check, const std::string& path, const Texture& texture) {
  if (texture.kind() != "wood" && texture.kind() != "checker") {
    check.Fail(path + ".kind",
               "is an unknown texture '" + texture.kind() + "' (expected wood or checker)");
  }
  if (texture.has_color()) check.Colour(path + ".color", texture.color());
  if (texture.has_scale()) check.Positive(path + ".scale", texture.scale(), 10.0);
}

void CheckSpawn(Checker& check, const std::string& path, const SpawnRegion& spawn) {
  check.FiniteVec(path + ".min", spawn.min());
  check.FiniteVec(path + ".max", spawn.max());
  const Eigen::Vector3d lo = ToEigen(spawn.min());
  const Eigen::Vector3d hi = ToEigen(spawn.max());
  const char* axes[] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    if (lo[a] > hi[a]) {
      check.Fail(path + ".min." + axes[a], "must be <= max." + std::string(axes[a]) + " (" +
                                               Num(hi[a]) + "), got " + Num(lo[a]));
    }
  }
  const std::string& o = spawn.orientation();
  if (!o.empty() && o != "yaw" && o != "full" && o != "fixed") {
    check.Fail(path + ".orientation", "is unknown: '" + o + "' (expected yaw, full or fixed)");
  }
  check.FiniteVec(path + ".base_rpy_deg", spawn.base_rpy_deg(), 3600);
}

void CheckBody(Checker& check, const std::string& path, const Body& body, BodyRole role,
               bool moveable) {
  CheckShape(check, path, body, role, moveable);
  if (body.has_color()) {
    check.Colour(path + ".color", body.color());
  } else if (role != BodyRole::kPart) {
    check.Missing(path + ".color", "every body needs an RGB colour");
  }
  if (body.has_texture()) CheckTexture(check, path + ".texture", body.texture());
  if (body.has_friction()) check.NonNegative(path + ".friction", body.friction(), 100.0);
  if (body.has_rolling_friction()) {
    check.NonNegative(path + ".rolling_friction", body.rolling_friction(), 1.0);
  }
  if (role == BodyRole::kObject) {
    check.NotAllowed(path + ".pose", body.has_pose(), "to objects: their pose comes from `spawn`");
    if (!body.has_mass()) {
      check.Missing(path + ".mass", "an object needs its mass in kg");
    } else {
      check.Positive(path + ".mass", body.mass(), 1000.0);
    }
    if (body.has_count() && (body.count() < 1 || body.count() > kMaxCount)) {
      check.Fail(path + ".count", "must be in [1, " + std::to_string(kMaxCount) + "], got " +
                                      std::to_string(body.count()));
    }
    if (!body.has_spawn()) {
      check.Missing(path + ".spawn", "an object needs a spawn region");
    } else {
      CheckSpawn(check, path + ".spawn", body.spawn());
    }
  } else {
    const std::string why = role == BodyRole::kStatic ? "to static bodies" : "to parts";
    check.NotAllowed(path + ".mass", body.has_mass(), why);
    check.NotAllowed(path + ".count", body.has_count(), why);
    check.NotAllowed(path + ".spawn", body.has_spawn(), why);
    if (body.has_pose()) {
      check.FiniteVec(path + ".pose.position", body.pose().position());
      check.FiniteVec(path + ".pose.rpy_deg", body.pose().rpy_deg(), 3600);
    }
  }
}

void CheckShape(Checker& check, const std::string& path, const Body& body, BodyRole role,
                bool moveable) {
  const std::string& shape = body.shape();
  const bool box = shape == "box", sphere = shape == "sphere", cylinder = shape == "cylinder",
             capsule = shape == "capsule", composite = shape == "composite", mesh = shape == "mesh";
  if (shape.empty()) {
    check.Missing(path + ".shape", "box, sphere, cylinder, capsule, composite or mesh");
    return;
  }
  if (!(box || sphere || cylinder || capsule || composite || mesh)) {
    check.Fail(path + ".shape", "is an unknown shape '" + shape +
                                    "' (expected box, sphere, cylinder, capsule, composite or "
                                    "mesh)");
    return;
  }
  const std::string to_this = "to a " + shape;
  check.NotAllowed(path + ".size", body.has_size() && !box, to_this);
  check.NotAllowed(path + ".radius", body.has_radius() && !(sphere || cylinder || capsule),
                   to_this);
  check.NotAllowed(path + ".length", body.has_length() && !(cylinder || capsule), to_this);
  check.NotAllowed(path + ".parts", body.parts_size() > 0 && !composite, to_this);
  check.NotAllowed(path + ".mesh", body.has_mesh() && !mesh, to_this);

  const std::string needs = "a " + shape + " needs it";
  if (box) {
    if (!body.has_size()) {
      check.Missing(path + ".size", needs);
    } else {
      check.PositiveVec(path + ".size", body.size());
    }
  }
  if (sphere || cylinder || capsule) {
    if (!body.has_radius()) {
      check.Missing(path + ".radius", needs);
    } else {
      check.Positive(path + ".radius", body.radius());
    }
  }
  if (cylinder || capsule) {
    if (!body.has_length()) {
      check.Missing(path + ".length", needs);
    } else {
      check.Positive(path + ".length", body.length());
    }
  }
  if (mesh) {
    if (!body.has_mesh()) {
      check.Missing(path + ".mesh", needs);
    } else {
      CheckMesh(check, path + ".mesh", body.mesh(), moveable);
    }
  }
  if (composite) {
    if (role == BodyRole::kPart) {
      check.Fail(path + ".shape", "cannot be composite inside a composite");
      return;
    }
    if (body.parts_size() == 0) {
      check.Missing(path + ".parts", "a composite needs at least one part");
    }
    for (int i = 0; i < body.parts_size(); ++i) {
      CheckBody(check, Index(path + ".parts", static_cast<std::size_t>(i)), body.parts(i),
                BodyRole::kPart, moveable);
    }
  }
}

void CheckSensorNoise(Checker& check, const std::string& path, const SensorNoise& n) {
  const auto non_negative = [&](const char* name, bool has, double v, double max) {
    if (has) check.NonNegative(path + "." + name, v, max);
  };
  non_negative("axial_constant", n.has_axial_constant(), n.axial_constant(), 0.5);
  non_negative("axial_quadratic", n.has_axial_quadratic(), n.axial_quadratic(), 0.5);
  non_negative("axial_offset", n.has_axial_offset(), n.axial_offset(), 10);
  non_negative("axial_grazing", n.has_axial_grazing(), n.axial_grazing(), 0.5);
  non_negative("lateral_constant_px", n.has_lateral_constant_px(), n.lateral_constant_px(), 20);
  non_negative("lateral_grazing_px", n.has_lateral_grazing_px(), n.lateral_grazing_px(), 20);
  if (n.has_ir_focal_px()) check.Positive(path + ".ir_focal_px", n.ir_focal_px(), 1e5);
  if (n.has_baseline()) check.Positive(path + ".baseline", n.baseline(), 1);
  if (n.has_disparity_steps_per_px()) {
    check.Positive(path + ".disparity_steps_per_px", n.disparity_steps_per_px(), 1024);
  }
  if (n.has_max_incidence_deg()) {
    const double v = n.max_incidence_deg();
    if (check.Finite(path + ".max_incidence_deg", v) && (v <= 0 || v >= 90)) {
      check.Fail(path + ".max_incidence_deg", "must be in (0, 90) degrees, got " + Num(v));
    }
  }
  if (n.has_edge_disparity_jump_px()) {
    check.Positive(path + ".edge_disparity_jump_px", n.edge_disparity_jump_px(), 1000);
  }
  if (n.has_edge_hole_probability()) {
    check.InRange(path + ".edge_hole_probability", n.edge_hole_probability(), 0, 1);
  }
  non_negative("color_noise_sigma", n.has_color_noise_sigma(), n.color_noise_sigma(), 255);
  non_negative("exposure_sigma", n.has_exposure_sigma(), n.exposure_sigma(), 0.5);
  non_negative("white_balance_sigma", n.has_white_balance_sigma(), n.white_balance_sigma(), 0.5);
}

void CheckCamera(Checker& check, const Camera& camera) {
  const std::string path = "camera";
  if (!camera.has_position()) {
    check.Missing(path + ".position", "the camera's position in the world, metres");
  } else {
    check.FiniteVec(path + ".position", camera.position());
  }
  if (camera.has_look_at() == camera.has_rpy_deg()) {
    check.Fail(path, "needs exactly one of look_at and rpy_deg");
  }
  if (camera.has_look_at()) {
    check.FiniteVec(path + ".look_at", camera.look_at());
    const Eigen::Vector3d forward = ToEigen(camera.look_at()) - ToEigen(camera.position());
    const Eigen::Vector3d up =
        camera.has_up() ? ToEigen(camera.up()) : Eigen::Vector3d::UnitZ().eval();
    if (camera.has_up()) check.FiniteVec(path + ".up", camera.up());
    if (forward.norm() < 1e-6) {
      check.Fail(path + ".look_at", "must differ from camera.position");
    } else if (up.norm() < 1e-9 || forward.normalized().cross(up.normalized()).norm() < 1e-3) {
      check.Fail(path + ".up", "must not be zero nor parallel to the viewing direction");
    }
  } else {
    check.NotAllowed(path + ".up", camera.has_up(), "with rpy_deg (only with look_at)");
    check.FiniteVec(path + ".rpy_deg", camera.rpy_deg(), 3600);
  }
  const auto side = [&](const char* name, bool has, std::uint32_t v) {
    if (has && (v < 1 || v > kMaxImageSide)) {
      check.Fail(path + "." + name, "must be in [1, " + std::to_string(kMaxImageSide) +
                                        "] pixels, got " + std::to_string(v));
    }
  };
  side("width", camera.has_width(), camera.width());
  side("height", camera.has_height(), camera.height());
  if (camera.has_fx()) check.Positive(path + ".fx", camera.fx(), 1e5);
  if (camera.has_fy()) check.Positive(path + ".fy", camera.fy(), 1e5);
  if (camera.has_cx()) check.InRange(path + ".cx", camera.cx(), -1e4, 1e4);
  if (camera.has_cy()) check.InRange(path + ".cy", camera.cy(), -1e4, 1e4);
  if (camera.has_horizontal_fov_deg()) {
    check.InRange(path + ".horizontal_fov_deg", camera.horizontal_fov_deg(), 1, 170);
    if (camera.has_fx()) check.Fail(path, "needs fx or horizontal_fov_deg, not both");
  }
  const bool ideal = camera.sensor() == "ideal";
  if (!ideal && !camera.sensor().empty() && camera.sensor() != "kinect_v1") {
    check.Fail(path + ".sensor",
               R"(must be "kinect_v1" or "ideal", got ")" + camera.sensor() + "\"");
  }
  if (camera.has_depth_noise_sigma()) {
    check.NotAllowed(path + ".depth_noise_sigma", !ideal,
                     "to the kinect_v1 sensor, which draws its own noise (only with \"sensor\": "
                     "\"ideal\"; tune camera.sensor_noise instead)");
    check.NonNegative(path + ".depth_noise_sigma", camera.depth_noise_sigma(), 0.5);
  }
  if (camera.has_sensor_noise()) {
    check.NotAllowed(path + ".sensor_noise", ideal, "to the ideal sensor");
    CheckSensorNoise(check, path + ".sensor_noise", camera.sensor_noise());
  }
  const CameraModel model = ResolveCamera(camera);
  check.NonNegative(path + ".min_range", model.min_range);
  check.Positive(path + ".max_range", model.max_range, 1000.0);
  if (model.min_range >= model.max_range) {
    check.Fail(path + ".min_range",
               "must be < max_range (" + Num(model.max_range) + "), got " + Num(model.min_range));
  }
}

void CheckPhysics(Checker& check, const Physics& p) {
  const std::string path = "physics";
  if (p.has_step_hz()) check.InRange(path + ".step_hz", p.step_hz(), 100, 10000);
  if (p.has_gravity()) check.NonNegative(path + ".gravity", p.gravity(), 100);
  if (p.has_effector_radius()) check.Positive(path + ".effector_radius", p.effector_radius(), 1);
  if (p.has_approach_distance()) {
    check.Positive(path + ".approach_distance", p.approach_distance(), 2);
  }
  if (p.has_overshoot()) check.NonNegative(path + ".overshoot", p.overshoot(), 2);
  if (p.has_push_speed()) check.Positive(path + ".push_speed", p.push_speed(), 10);
  if (p.has_clearance()) check.NonNegative(path + ".clearance", p.clearance(), 1);
  if (p.has_rest_linear_speed()) {
    check.Positive(path + ".rest_linear_speed", p.rest_linear_speed(), 10);
  }
  if (p.has_rest_angular_speed_deg()) {
    check.Positive(path + ".rest_angular_speed_deg", p.rest_angular_speed_deg(), 3600);
  }
  if (p.has_settle_time_cap()) check.Positive(path + ".settle_time_cap", p.settle_time_cap(), 60);
}

}  // namespace

Status ValidateScene(const Scene& scene, const std::string& file_label) {
  Checker check(file_label);
  if (scene.name().empty()) check.Missing("name", "the scene's name");
  if (!scene.has_camera()) {
    check.Missing("camera", "position, look_at or rpy_deg, and intrinsics");
  } else {
    CheckCamera(check, scene.camera());
  }
  if (scene.has_light()) {
    const Light& light = scene.light();
    if (light.has_direction()) {
      check.FiniteVec("light.direction", light.direction());
      if (ToEigen(light.direction()).norm() < 1e-9) {
        check.Fail("light.direction", "must not be zero");
      }
    }
    if (light.has_ambient()) check.InRange("light.ambient", light.ambient(), 0, 1);
  }
  for (int i = 0; i < scene.static_bodies_size(); ++i) {
    CheckBody(check, Index("static_bodies", static_cast<std::size_t>(i)), scene.static_bodies(i),
              BodyRole::kStatic, /*moveable=*/false);
  }
  if (scene.objects_size() == 0) {
    check.Missing("objects", "a scene needs at least one moveable object");
  }
  auto body_count = static_cast<std::size_t>(scene.static_bodies_size());
  for (int i = 0; i < scene.objects_size(); ++i) {
    CheckBody(check, Index("objects", static_cast<std::size_t>(i)), scene.objects(i),
              BodyRole::kObject, /*moveable=*/true);
    body_count += ObjectCount(scene.objects(i));
  }
  if (body_count > kMaxBodies) {
    check.Fail("objects", "make " + std::to_string(body_count) + " bodies; at most " +
                              std::to_string(kMaxBodies) + " are supported");
  }
  if (scene.has_motion_threshold()) {
    check.Positive("motion_threshold", scene.motion_threshold(), 1.0);
  }
  if (scene.has_physics()) CheckPhysics(check, scene.physics());
  return check.Result();
}

}  // namespace relmap::sim
