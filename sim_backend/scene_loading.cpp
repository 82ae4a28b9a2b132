// The one place that names OdeScene: compiled against the world when CMake found the
// relmap_sim_world target (RELMAP_SIM_WITH_WORLD).
#include "scene_loading.h"

#include <utility>

#ifdef RELMAP_SIM_WITH_WORLD
#include "ode_scene.h"
#endif

namespace relmap::sim {

#ifdef RELMAP_SIM_WITH_WORLD

StatusOr<std::unique_ptr<SimulatedScene>> LoadOdeScene(const std::string& name_or_path,
                                                       std::uint64_t seed) {
  StatusOr<std::unique_ptr<OdeScene>> loaded = OdeScene::Load(name_or_path, seed);
  if (!loaded.ok()) return loaded.status();
  return std::unique_ptr<SimulatedScene>(std::move(*loaded));
}

StatusOr<std::unique_ptr<SimulatedScene>> LoadOdeSceneOfSize(const std::string& name_or_path,
                                                             std::uint64_t seed,
                                                             std::uint32_t width,
                                                             std::uint32_t height) {
  StatusOr<std::unique_ptr<OdeScene>> loaded = OdeScene::Load(name_or_path, seed);
  if (!loaded.ok()) return loaded.status();
  (*loaded)->SetImageSize(width, height);
  return std::unique_ptr<SimulatedScene>(std::move(*loaded));
}

#else

StatusOr<std::unique_ptr<SimulatedScene>> LoadOdeScene(const std::string& name_or_path,
                                                       std::uint64_t /*seed*/) {
  return Status(StatusCode::kUnimplemented,
                "the ODE world (relmap_sim_world) is not built yet: cannot load scene '" +
                    name_or_path + "'");
}

StatusOr<std::unique_ptr<SimulatedScene>> LoadOdeSceneOfSize(const std::string& name_or_path,
                                                             std::uint64_t seed, std::uint32_t,
                                                             std::uint32_t) {
  return LoadOdeScene(name_or_path, seed);
}

#endif

StatusOr<std::unique_ptr<SimulatedScene>> LoadOdeSceneAt(const std::string& name_or_path,
                                                         std::uint64_t seed,
                                                         const std::optional<ImageSize>& size) {
  if (!size) return LoadOdeScene(name_or_path, seed);
  return LoadOdeSceneOfSize(name_or_path, seed, size->width, size->height);
}

}  // namespace relmap::sim
