// MakeSimulatedRobot in a relmap-robot built without the simulator.
#include "simulated_robot.h"

namespace relmap::robot {

StatusOr<std::unique_ptr<SimulatedRobot>> MakeSimulatedRobot(const SimConfig& /*config*/) {
  return FailedPreconditionError(
      "this relmap-robot was built without the simulator (RELMAP_ROBOT_WITH_SIM=OFF): "
      "use a camera source and driver, or rebuild with -DRELMAP_ROBOT_WITH_SIM=ON");
}

}  // namespace relmap::robot
