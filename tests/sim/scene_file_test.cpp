// Scene files: the shipped ones and the benchmark ones parse, and bad ones are
// refused with errors that name the file and the field.
#include "scene_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace relmap::sim {
namespace {

using ::testing::HasSubstr;

// A valid scene with `object` as its only object.
std::string SceneWith(const std::string& object) {
  return R"({
    "name": "Tiny",
    "camera": {"position": {"x": -1, "z": 1}, "look_at": {"x": 0, "y": 0, "z": 0}},
    "static_bodies": [{"name": "table", "shape": "box", "size": {"x": 1, "y": 1, "z": 0.1},
                       "color": {"r": 200, "g": 200, "b": 200},
                       "pose": {"position": {"z": -0.05}}}],
    "objects": [)" +
         object + R"(]
  })";
}

constexpr char kBall[] = R"({"shape": "sphere", "radius": 0.03, "color": {"r": 1},
    "mass": 0.1, "spawn": {"min": {"z": 0.03}, "max": {"z": 0.03}}})";

std::string ErrorOf(const std::string& json, const std::string& label = "Tiny.json") {
  const StatusOr<Scene> scene = ParseScene(json, label);
  EXPECT_FALSE(scene.ok());
  return scene.ok() ? "" : scene.status().message();
}

// The benchmark scenes (issue 13) live in <scenes>/benchmark/: loaded by path, not
// listed as shipped scenes.
std::vector<std::string> BenchmarkSceneFiles() {
  std::vector<std::string> files;
  std::error_code error;
  const std::filesystem::path folder = std::filesystem::path(ScenesDirectory()) / "benchmark";
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    if (entry.is_regular_file() && entry.path().extension() == ".json") {
      files.push_back(entry.path().string());
    }
  }
  return files;
}

void ExpectEachParsesAndNamesItselfAfterItsFile(const std::vector<std::string>& paths) {
  for (const std::string& path : paths) {
    SCOPED_TRACE(path);
    const StatusOr<SceneFile> file = ReadSceneFile(path);
    ASSERT_TRUE(file.ok()) << file.status().message();
    EXPECT_EQ(file->scene.name(), std::filesystem::path(path).stem().string());
    EXPECT_GT(file->scene.objects_size(), 0);
  }
}

TEST(SceneFile, ShipsThePapersSixSetups) {
  std::vector<std::string> names;
  for (const std::string& path : ShippedSceneFiles()) {
    names.push_back(std::filesystem::path(path).stem().string());
  }
  EXPECT_THAT(names,
              ::testing::IsSupersetOf({"MoveableBalls", "MoveableBricks1", "MoveableBricks2",
                                       "WhiteMoveableBalls", "WhiteMoveableBricks", "SimKitchen"}));
}

TEST(SceneFile, EveryShippedSceneParsesAndNamesItselfAfterItsFile) {
  ExpectEachParsesAndNamesItselfAfterItsFile(ShippedSceneFiles());
}

TEST(SceneFile, EveryBenchmarkSceneParsesAndNamesItselfAfterItsFile) {
  const std::vector<std::string> files = BenchmarkSceneFiles();
  EXPECT_FALSE(files.empty()) << "no scene files in " << ScenesDirectory() << "/benchmark";
  ExpectEachParsesAndNamesItselfAfterItsFile(files);
}

TEST(SceneFile, FindsAShippedSceneByNameOrByPath) {
  const StatusOr<std::string> by_name = FindSceneFile("MoveableBalls");
  ASSERT_TRUE(by_name.ok()) << by_name.status().message();
  EXPECT_EQ(std::filesystem::path(*by_name).filename(), "MoveableBalls.json");
  const StatusOr<std::string> by_path = FindSceneFile(*by_name);
  ASSERT_TRUE(by_path.ok());
  EXPECT_EQ(*by_path, *by_name);
}

TEST(SceneFile, AnUnknownSceneIsNotFoundAndTheShippedOnesAreListed) {
  const StatusOr<std::string> found = FindSceneFile("NoSuchScene");
  ASSERT_FALSE(found.ok());
  EXPECT_EQ(found.status().code(), StatusCode::kNotFound);
  EXPECT_THAT(found.status().message(), HasSubstr("NoSuchScene"));
  EXPECT_THAT(found.status().message(), HasSubstr("MoveableBalls"));
}

TEST(SceneFile, AcceptsAMinimalScene) {
  const StatusOr<Scene> scene = ParseScene(SceneWith(kBall), "Tiny.json");
  EXPECT_TRUE(scene.ok()) << scene.status().message();
}

TEST(SceneFile, ANegativeSizeNamesTheFileTheFieldAndTheValue) {
  const std::string brick = R"({"shape": "box", "size": {"x": -0.1, "y": 0.05, "z": 0.05},
      "color": {"r": 1}, "mass": 0.1, "spawn": {}})";
  EXPECT_EQ(ErrorOf(SceneWith(brick), "MoveableBricks1.json"),
            "MoveableBricks1.json: objects[0].size.x must be > 0, got -0.1");
}

TEST(SceneFile, AMissingFieldIsNamedWithWhatNeedsIt) {
  const std::string no_radius = R"({"shape": "sphere", "color": {"r": 1}, "mass": 0.1,
      "spawn": {}})";
  EXPECT_THAT(ErrorOf(SceneWith(no_radius)),
              HasSubstr("Tiny.json: objects[0].radius is missing (a sphere needs it)"));
  const std::string no_mass = R"({"shape": "sphere", "radius": 0.03, "color": {"r": 1},
      "spawn": {}})";
  EXPECT_THAT(ErrorOf(SceneWith(no_mass)), HasSubstr("objects[0].mass is missing"));
  EXPECT_THAT(ErrorOf(R"({"name": "NoCamera", "objects": [)" + std::string(kBall) + "]}"),
              HasSubstr("Tiny.json: camera is missing"));
}

TEST(SceneFile, AnUnknownShapeListsTheKnownOnes) {
  const std::string cone = R"({"shape": "cone", "color": {"r": 1}, "mass": 0.1, "spawn": {}})";
  EXPECT_THAT(ErrorOf(SceneWith(cone)),
              HasSubstr("objects[0].shape is an unknown shape 'cone' (expected box, sphere, "
                        "cylinder, capsule, composite or mesh)"));
}

TEST(SceneFile, AnUnknownTextureListsTheKnownOnes) {
  const std::string marble = R"({"shape": "sphere", "radius": 0.03, "color": {"r": 1},
      "texture": {"kind": "marble"}, "mass": 0.1, "spawn": {}})";
  EXPECT_THAT(ErrorOf(SceneWith(marble)),
              HasSubstr("objects[0].texture.kind is an unknown texture 'marble' (expected wood "
                        "or checker)"));
}

TEST(SceneFile, MalformedJsonNamesTheFile) {
  const std::string message = ErrorOf(R"({"name": "Broken", "objects": [)");
  EXPECT_THAT(message, HasSubstr("Tiny.json: not a valid scene file"));
}

TEST(SceneFile, AnUnknownFieldIsAnErrorNotIgnored) {
  const std::string message = ErrorOf(SceneWith(R"({"shape": "sphere", "radius": 0.03,
      "colour": {"r": 1}, "mass": 0.1, "spawn": {}})"));
  EXPECT_THAT(message, HasSubstr("Tiny.json: not a valid scene file"));
  EXPECT_THAT(message, HasSubstr("colour"));
}

TEST(SceneFile, FieldsThatDoNotApplyToTheShapeAreRefused) {
  EXPECT_THAT(ErrorOf(SceneWith(R"({"shape": "sphere", "radius": 0.03, "length": 0.1,
      "color": {"r": 1}, "mass": 0.1, "spawn": {}})")),
              HasSubstr("objects[0].length does not apply to a sphere"));
}

TEST(SceneFile, EveryProblemIsReportedOnItsOwnLine) {
  const std::string message = ErrorOf(SceneWith(R"({"shape": "box",
      "size": {"x": 0, "y": -1, "z": 0.1}, "color": {"r": 300}, "mass": -2, "spawn": {}})"));
  EXPECT_THAT(message, HasSubstr("Tiny.json: objects[0].size.x must be > 0, got 0\n"));
  EXPECT_THAT(message, HasSubstr("Tiny.json: objects[0].size.y must be > 0, got -1\n"));
  EXPECT_THAT(message, HasSubstr("Tiny.json: objects[0].color.r must be in [0, 255], got 300"));
  EXPECT_THAT(message, HasSubstr("Tiny.json: objects[0].mass must be > 0, got -2"));
}

TEST(SceneFile, NonFiniteNumbersAreRefused) {
  EXPECT_THAT(ErrorOf(SceneWith(R"({"shape": "sphere", "radius": "NaN", "color": {"r": 1},
      "mass": 0.1, "spawn": {}})")),
              HasSubstr("objects[0].radius must be a finite number, got nan"));
}

TEST(SceneFile, ASpawnRegionMustNotBeInsideOut) {
  EXPECT_THAT(ErrorOf(SceneWith(R"({"shape": "sphere", "radius": 0.03, "color": {"r": 1},
      "mass": 0.1, "spawn": {"min": {"x": 0.2}, "max": {"x": 0.1}}})")),
              HasSubstr("objects[0].spawn.min.x must be <= max.x (0.1), got 0.2"));
}

TEST(SceneFile, CompositesNestOneLevelOnly) {
  EXPECT_THAT(ErrorOf(SceneWith(R"({"shape": "composite", "color": {"r": 1}, "mass": 0.1,
      "spawn": {}, "parts": [{"shape": "composite", "parts": []}]})")),
              HasSubstr("objects[0].parts[0].shape cannot be composite inside a composite"));
}

TEST(SceneFile, AMeshMustIndexItsVerticesAndAMoveableOneMustBeClosed) {
  EXPECT_THAT(ErrorOf(SceneWith(R"({"shape": "mesh", "color": {"r": 1}, "mass": 0.1,
      "spawn": {}, "mesh": {"vertices": [0, 0, 0, 1, 0, 0, 0, 1, 0], "indices": [0, 1, 3]}})")),
              HasSubstr("objects[0].mesh.indices[2] must be < 3 (the vertex count), got 3"));
  // One triangle encloses no volume: it cannot have a mass distribution.
  EXPECT_THAT(ErrorOf(SceneWith(R"({"shape": "mesh", "color": {"r": 1}, "mass": 0.1,
      "spawn": {}, "mesh": {"vertices": [0, 0, 0, 1, 0, 0, 0, 1, 0], "indices": [0, 1, 2]}})")),
              HasSubstr("objects[0].mesh must be closed with outward triangles"));
}

TEST(SceneFile, TheCameraNeedsExactlyOneOrientation) {
  const std::string both = R"({"name": "Both", "camera": {"position": {"x": -1},
      "look_at": {}, "rpy_deg": {}}, "objects": [)" +
                           std::string(kBall) + "]}";
  EXPECT_THAT(ErrorOf(both), HasSubstr("camera needs exactly one of look_at and rpy_deg"));
}

// The minimal scene with `fields` added to its camera.
std::string CameraWith(const std::string& fields) {
  std::string json = SceneWith(kBall);
  const std::string look_at = R"("look_at": {"x": 0, "y": 0, "z": 0})";
  return json.replace(json.find(look_at), look_at.size(), look_at + ", " + fields);
}

TEST(SceneFile, TheCameraIsAKinectOrIdeal) {
  EXPECT_TRUE(ParseScene(CameraWith(R"("sensor": "ideal")"), "Tiny.json").ok());
  EXPECT_TRUE(ParseScene(CameraWith(R"("sensor": "kinect_v1")"), "Tiny.json").ok());
  EXPECT_THAT(ErrorOf(CameraWith(R"("sensor": "kinect_v2")")),
              HasSubstr("Tiny.json: camera.sensor must be \"kinect_v1\" or \"ideal\", got "
                        "\"kinect_v2\""));
}

TEST(SceneFile, DepthNoiseSigmaIsTheIdealSensorsOnly) {
  EXPECT_TRUE(
      ParseScene(CameraWith(R"("sensor": "ideal", "depth_noise_sigma": 0.01)"), "Tiny.json").ok());
  EXPECT_THAT(ErrorOf(CameraWith(R"("depth_noise_sigma": 0.01)")),
              HasSubstr("camera.depth_noise_sigma does not apply to the kinect_v1 sensor"));
  EXPECT_THAT(ErrorOf(CameraWith(R"("sensor": "ideal", "sensor_noise": {"baseline": 0.05})")),
              HasSubstr("camera.sensor_noise does not apply to the ideal sensor"));
}

TEST(SceneFile, SensorNoiseFiguresAreChecked) {
  EXPECT_TRUE(ParseScene(CameraWith(R"("sensor_noise": {"axial_constant": 0.002,
      "baseline": 0.05, "max_incidence_deg": 80, "edge_hole_probability": 1})"),
                         "Tiny.json")
                  .ok());
  const std::string message = ErrorOf(CameraWith(R"("sensor_noise": {"axial_quadratic": -1,
      "baseline": 0, "max_incidence_deg": 90, "edge_hole_probability": 1.5,
      "disparity_steps_per_px": 0})"));
  EXPECT_THAT(message, HasSubstr("camera.sensor_noise.axial_quadratic must be >= 0, got -1"));
  EXPECT_THAT(message, HasSubstr("camera.sensor_noise.baseline must be > 0, got 0"));
  EXPECT_THAT(
      message,
      HasSubstr("camera.sensor_noise.max_incidence_deg must be in (0, 90) degrees, got 90"));
  EXPECT_THAT(message,
              HasSubstr("camera.sensor_noise.edge_hole_probability must be in [0, 1], got 1.5"));
  EXPECT_THAT(message, HasSubstr("camera.sensor_noise.disparity_steps_per_px must be > 0, got 0"));
}

}  // namespace
}  // namespace relmap::sim
