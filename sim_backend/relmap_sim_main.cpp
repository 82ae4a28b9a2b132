// relmap-sim: the ODE-simulated pusher and experiment runner (issue 5). Each command
// gets the arguments from its own name on (argv[0] = "scenes", "render", "run" or
// "dataset").
#include <cstdio>
#include <string_view>

#include "common/command_line.h"
#include "sim_commands.h"

namespace {

constexpr char kUsage[] =
    "usage: relmap-sim <command> [flags]\n"
    "  scenes                                   the shipped scenes\n"
    "  render --scene <name|file> --png out.png [--seed S]\n"
    "                                           the camera view with a ground-truth overlay\n"
    "  run --scene <name|file> --out DIR ...    an experiment (relmap-sim run --help)\n"
    "  dataset --scene <name|file> --out F.csv  labelled supervoxel features of re-spawned\n"
    "                                           frames (relmap-sim dataset --help)\n"
    "Exit codes: 0 success, 1 a failed run or server error, 2 bad arguments or files.\n";

#ifndef RELMAP_SIM_WITH_SCENE_COMMANDS
// Until relmap_sim_scene_commands is built (the ODE world's commands).
int NotBuiltYet(const char* command) {
  std::fprintf(stderr, "relmap-sim %s: the ODE world is not built yet\n", command);
  return 1;
}
#endif

int Main(int argc, char** argv) {
  const std::string_view command = argc >= 2 ? argv[1] : "";
  if (command == "run") return relmap::sim::RunExperimentCommand(argc - 1, argv + 1);
  if (command == "dataset") return relmap::sim::RunDatasetCommand(argc - 1, argv + 1);
  if (command == "scenes" || command == "render") {
#ifdef RELMAP_SIM_WITH_SCENE_COMMANDS
    return command == "scenes" ? relmap::sim::RunScenesCommand(argc - 1, argv + 1)
                               : relmap::sim::RunRenderCommand(argc - 1, argv + 1);
#else
    return NotBuiltYet(argv[1]);
#endif
  }
  if (command == "--help" || command == "-h" || command == "help") {
    std::fputs(kUsage, stdout);
    return 0;
  }
  std::fprintf(stderr, "%s%s", command.empty() ? "" : "relmap-sim: unknown command\n", kUsage);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  return relmap::tools::ExitCodeOf("relmap-sim", [&] { return Main(argc, argv); });
}
