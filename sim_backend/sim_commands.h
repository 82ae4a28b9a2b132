// The subcommands of relmap-sim, one function each; each returns the exit code
// (0 success, 1 a failed run or server error, 2 bad arguments or files).
#pragma once

#include <cstdio>
#include <string>

namespace relmap::sim {

// How a subcommand fails: "relmap-sim <command>: <message>" on standard error; returns
// `code`, the exit code.
inline int FailCommand(const char* command, const std::string& message, int code) {
  std::fprintf(stderr, "relmap-sim %s: %s\n", command, message.c_str());
  return code;
}

// relmap-sim scenes: the shipped scenes, one line each (name, file, objects).
int RunScenesCommand(int argc, char** argv);
// relmap-sim render --scene <name|file> --png out.png [--seed S]: the camera view
// with a ground-truth overlay (moveable bodies tinted), to check a scene by eye.
int RunRenderCommand(int argc, char** argv);
// relmap-sim run ...: the experiment runner.
int RunExperimentCommand(int argc, char** argv);
// relmap-sim dataset ...: labelled supervoxel features of re-spawned frames, as CSV.
int RunDatasetCommand(int argc, char** argv);

}  // namespace relmap::sim
