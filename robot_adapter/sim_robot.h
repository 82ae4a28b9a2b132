// The simulator of sim_backend as a stand-in robot, for tests and demos: its camera
// as a cloud source (which knows the ground truth), its pusher as a driver. Both use
// one scene, which outlives them.
#pragma once

#include <cstdint>

#include "cloud_source.h"
#include "pusher_driver.h"
#include "simulated_scene.h"

namespace relmap::robot {

class SimSource final : public CloudSource {
 public:
  explicit SimSource(sim::SimulatedScene& scene) : scene_(scene) {}
  // A capture of the scene as it is now, packed; never ends.
  StatusOr<std::optional<SourceFrame>> Next() override;

 private:
  sim::SimulatedScene& scene_;
};

class SimDriver final : public PusherDriver {
 public:
  // Push directions are drawn from `seed` and the target's iteration and attempt.
  SimDriver(sim::SimulatedScene& scene, std::uint64_t seed) : scene_(scene), seed_(seed) {}
  // Done when the pusher reached the target, unreachable when every approach was
  // blocked; never a label of its own (the server's change detector decides).
  StatusOr<PushOutcome> Push(const DriverRequest& target) override;

 private:
  sim::SimulatedScene& scene_;
  std::uint64_t seed_;
};

}  // namespace relmap::robot
