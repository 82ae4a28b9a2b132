// The simulator as relmap-robot's camera and arm, behind a link-time switch: with
// RELMAP_ROBOT_WITH_SIM (the default) sim_robot.cpp makes it from sim_backend's ODE
// scene; without, no_simulator.cpp refuses the sim source, and relmap-robot links
// neither ODE nor the simulator.
#pragma once

#include <memory>

#include "cloud_source.h"
#include "common/status.h"
#include "pusher_driver.h"
#include "robot_messages.pb.h"

namespace relmap::robot {

// One simulated scene, seen by its camera and pushed by its pusher. The source and
// driver it makes refer to the scene: it outlives them.
class SimulatedRobot {
 public:
  virtual ~SimulatedRobot() = default;
  virtual std::unique_ptr<CloudSource> Source() = 0;
  virtual std::unique_ptr<PusherDriver> Driver() = 0;
};

// The scene of `config`, at its image size when one is given. FAILED_PRECONDITION in a
// relmap-robot built without the simulator; the scene loader's errors otherwise.
StatusOr<std::unique_ptr<SimulatedRobot>> MakeSimulatedRobot(const SimConfig& config);

}  // namespace relmap::robot
