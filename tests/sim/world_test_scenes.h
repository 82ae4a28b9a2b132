// Tiny scene files for the world's tests, written inline so that every
// expected value can be computed by hand.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "ode_scene.h"

namespace relmap::sim::testing {

// A camera at the world origin looking along +x (so the camera's x is world -y,
// its y is world -z), 65 x 49 pixels, fx = fy = 50, principal point (32, 24):
// pixel (u, v) looks along ((u - 32) / 50, (v - 24) / 50, 1). The ideal sensor,
// so that every depth is exact.
inline constexpr char kAxisCamera[] = R"("camera": {"sensor": "ideal",
    "position": {"x": 0, "y": 0, "z": 0}, "look_at": {"x": 1, "y": 0, "z": 0},
    "width": 65, "height": 49, "fx": 50, "fy": 50, "cx": 32, "cy": 24})";

inline std::unique_ptr<OdeScene> LoadOrDie(const std::string& json, std::uint64_t seed = 1) {
  StatusOr<std::unique_ptr<OdeScene>> scene = OdeScene::FromJson(json, "test.json", seed);
  EXPECT_TRUE(scene.ok()) << scene.status().message();
  return scene.ok() ? std::move(scene).value() : nullptr;
}

}  // namespace relmap::sim::testing
