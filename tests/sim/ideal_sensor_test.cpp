// The ideal camera ("sensor": "ideal") reproduces the frames relmap-sim rendered
// before the structured-light sensor model existed: checksums recorded from that
// renderer (commit "sim tests: checksums of today's ideal camera frames").
#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>

#include "scene_file.h"
#include "world_test_scenes.h"

namespace relmap::sim {
namespace {

using testing::LoadOrDie;

// FNV-1a over every byte the frame carries (point coordinates as their float
// bits, colours, body ids): any change to any pixel changes it.
std::uint64_t Checksum(const CameraFrame& frame) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  const auto mix = [&](const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 0x100000001b3ull;
  };
  for (const CameraPoint& p : frame.points) {
    const float xyz[3] = {p.x, p.y, p.z};
    mix(xyz, sizeof xyz);
    const std::uint8_t rgb[3] = {p.r, p.g, p.b};
    mix(rgb, sizeof rgb);
  }
  mix(frame.body_ids.data(), frame.body_ids.size() * sizeof(std::int32_t));
  return hash;
}

// A box, a sphere and a mesh in front of a wall, textured, seen by the axis
// camera with its depth noise on.
std::string Tabletop(const std::string& camera_extra) {
  return std::string(R"({"name": "Checksum", "camera": {"sensor": "ideal",
      "position": {"x": 0, "y": 0, "z": 0}, "look_at": {"x": 1, "y": 0, "z": 0},
      "width": 65, "height": 49, "fx": 50, "fy": 50, "cx": 32, "cy": 24)") +
         camera_extra + R"(},
    "static_bodies": [
      {"shape": "box", "size": {"x": 0.2, "y": 0.4, "z": 0.4}, "color": {"r": 200, "g": 90},
       "texture": {"kind": "wood"}, "pose": {"position": {"x": 1.1}, "rpy_deg": {"z": 20}}},
      {"shape": "box", "size": {"x": 0.1, "y": 8, "z": 8}, "color": {"g": 255},
       "texture": {"kind": "checker"}, "pose": {"position": {"x": 3}}},
      {"shape": "mesh", "color": {"r": 255, "b": 90},
       "mesh": {"vertices": [2, -1, -1, 2, -0.5, -1, 2, -0.5, -0.5],
                "indices": [0, 2, 1]}}],
    "objects": [
      {"shape": "sphere", "radius": 0.1, "color": {"b": 255}, "mass": 0.1,
       "spawn": {"min": {"x": 1.5, "y": 0.6}, "max": {"x": 1.5, "y": 0.6},
                 "orientation": "fixed"}}],
    "physics": {"gravity": 0}})";
}

TEST(IdealSensor, RendersTodaysExactFrames) {
  auto scene = LoadOrDie(Tabletop(""));
  EXPECT_EQ(Checksum(scene->Capture()), 12974563671588632465ull);
}

TEST(IdealSensor, DrawsTodaysDepthNoise) {
  auto scene = LoadOrDie(Tabletop(R"(, "depth_noise_sigma": 0.01)"), 5);
  EXPECT_EQ(Checksum(scene->Capture()), 13655525613272874293ull);
  EXPECT_EQ(Checksum(scene->Capture()), 2295247752365421640ull);
}

TEST(IdealSensor, RendersTodaysShippedSceneAt640x480) {
  StatusOr<SceneFile> file = ReadSceneFile("MoveableBricks1");
  ASSERT_TRUE(file.ok()) << file.status().message();
  file->scene.mutable_camera()->set_sensor("ideal");
  std::string json;
  ASSERT_TRUE(google::protobuf::util::MessageToJsonString(file->scene, &json).ok());
  auto scene = LoadOrDie(json, 3);
  scene->SetImageSize(640, 480);
  EXPECT_EQ(Checksum(scene->Capture()), 5732283466208234087ull);
}

}  // namespace
}  // namespace relmap::sim
