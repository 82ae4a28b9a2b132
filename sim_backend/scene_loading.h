// The shipped scenes (and scene files) for the runner: OdeScene::Load of the ODE world
// behind the SimulatedScene interface. Until relmap_sim_world is built, every load
// answers UNIMPLEMENTED ("not built yet").
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "common/status.h"
#include "image_size.h"
#include "simulated_scene.h"

namespace relmap::sim {

// A new instance of the scene named `name_or_path` (a shipped scene's name or a scene
// file) drawn from `seed`; its errors are the world's (unknown scene, bad file).
StatusOr<std::unique_ptr<SimulatedScene>> LoadOdeScene(const std::string& name_or_path,
                                                       std::uint64_t seed);
// The same rendered at `width`×`height` pixels, the scene camera's field of view kept
// (as `relmap-sim render --width --height`).
StatusOr<std::unique_ptr<SimulatedScene>> LoadOdeSceneOfSize(const std::string& name_or_path,
                                                             std::uint64_t seed,
                                                             std::uint32_t width,
                                                             std::uint32_t height);
// LoadOdeSceneOfSize when `size` is given, else LoadOdeScene (the commands' --resolution).
StatusOr<std::unique_ptr<SimulatedScene>> LoadOdeSceneAt(const std::string& name_or_path,
                                                         std::uint64_t seed,
                                                         const std::optional<ImageSize>& size);

}  // namespace relmap::sim
