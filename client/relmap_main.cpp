// relmap: the command-line client of relmap-server (usage in cli_arguments.cpp).
#include <cstdio>
#include <string>
#include <string_view>

#include "cli_commands.h"

int main(int argc, char** argv) {
  using namespace relmap::client;
  if (argc < 2 || std::string_view(argv[1]) == "--help" || std::string_view(argv[1]) == "help") {
    std::fputs(kCliUsage, argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  const std::string command = argv[1];
  if (command == "session") {
    if (argc < 3) UsageError("session needs a verb: create, list, show, delete, export, import");
    return RunSessionCommand(argv[2], CommandLine(argc, argv, 3));
  }
  const CommandLine args(argc, argv, 2);
  if (command == "maps") return RunMaps(args);
  if (command == "outcome") return RunOutcome(args);
  if (command == "stream") return RunStream(args);
  if (command == "health") return RunHealth(args);
  UsageError("unknown command '" + command + "'");
}
