// The synthetic tabletop's points through MakeCloud.
#include "perception/synthetic_tabletop.h"

namespace relmap::perception {

SyntheticTabletop MakeSyntheticTabletop(const SyntheticTabletopOptions& options) {
  synthetic::Tabletop scene = synthetic::MakeTabletop(options);
  return {MakeCloud(scene.width, scene.height, std::move(scene.points)).value(),
          std::move(scene.object_of_point), scene.objects};
}

}  // namespace relmap::perception
