// The six shipped setups as the camera sees them: the table fills most of the
// view and every moveable object is in sight.
#include <gtest/gtest.h>

#include <map>

#include "ode_scene.h"

namespace relmap::sim {
namespace {

class ShippedScene : public ::testing::TestWithParam<const char*> {};

TEST_P(ShippedScene, LoadsAndShowsEveryObjectOnTheTable) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    StatusOr<std::unique_ptr<OdeScene>> loaded = OdeScene::Load(GetParam(), seed);
    ASSERT_TRUE(loaded.ok()) << loaded.status().message();
    OdeScene& scene = **loaded;
    EXPECT_EQ(scene.name(), GetParam());
    EXPECT_EQ(scene.last_respawn_failures(), 0);
    const CameraFrame frame = scene.Capture();
    EXPECT_EQ(frame.width, 320u);
    EXPECT_EQ(frame.height, 240u);
    std::map<std::int32_t, int> pixels;
    for (const std::int32_t id : frame.body_ids) ++pixels[id];
    // The table (or counter) top is the second static body in every shipped scene.
    const double support =
        static_cast<double>(pixels[1]) / static_cast<double>(frame.body_ids.size());
    EXPECT_GT(support, 0.45) << scene.body_name(1);
    for (const std::int32_t id : scene.moveable_bodies()) {
      EXPECT_GE(pixels[id], 40) << scene.body_name(id) << " seed " << seed;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(PapersSetups, ShippedScene,
                         ::testing::Values("MoveableBalls", "MoveableBricks1", "MoveableBricks2",
                                           "WhiteMoveableBalls", "WhiteMoveableBricks",
                                           "SimKitchen"));

}  // namespace
}  // namespace relmap::sim
