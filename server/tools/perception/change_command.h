// relmap-perception --change before.pcd after.pcd --target-point x,y,z: the change
// detector's evidence for the supervoxel nearest the point, as one JSON line.
#pragma once

namespace relmap::tools {

// The process's exit code: 0, or 1 with a message on standard error.
int RunChangeCommand(int argc, char** argv);

}  // namespace relmap::tools
