// The one check of a parsed scene file against every constraint its schema
// states (scene_schema.proto), so that nothing invalid reaches ODE, which aborts
// the process on misuse.
#pragma once

#include <string>

#include "common/status.h"
#include "scene_schema.pb.h"

namespace relmap::sim {

// OK, or InvalidArgument naming the file and the field path of every problem,
// one per line: "MoveableBricks1.json: objects[2].size.x must be > 0, got -0.1".
Status ValidateScene(const Scene& scene, const std::string& file_label);

}  // namespace relmap::sim
