// Flag parsing: strict numbers, one place for the usage text and the checks.
#include "load_options.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string_view>

#include "common/command_line.h"

namespace relmap::load {
namespace {

constexpr char kProgram[] = "relmap-load";

constexpr std::string_view kUsage =
    "usage: relmap-load [--sessions 8] [--cycles 20 | --seconds T] [--seed 1]\n"
    "                   [--synthetic 320x240 | --cloud FILE.pcd]\n"
    "                   [--server-binary PATH] [--max-threads N] [--memory-only]\n"
    "                   [--server HOST:PORT [--server-pid PID] [--admin-key-file F]]\n"
    "                   [--deadline-seconds 120] [--max-attempts N] [--json]\n"
    "                   [--soak-rounds R [--rest-seconds 20] [--csv F] [--png F]\n"
    "                    [--max-rested-growth-mib M]]\n"
    "  Runs S concurrent sessions against one relmap-server, each looping ComputeMaps ->\n"
    "  PostOutcome on the returned target, and reports throughput, client-observed\n"
    "  latencies and the server's resident memory per session.\n"
    "  --sessions        concurrent sessions S\n"
    "  --cycles          push cycles per session (with --seconds too: whichever ends first)\n"
    "  --seconds         no session starts a cycle after T seconds\n"
    "  --seed            derives every session seed and label; same seed, same run\n"
    "  --synthetic WxH   the synthetic tabletop (default), labelled by its ground truth\n"
    "  --cloud FILE      a PCD file sent as it is, labelled by a seeded coin\n"
    "  --server-binary   the server to start on 127.0.0.1:0 with a temporary --data-dir\n"
    "                    (default: the one built with this program)\n"
    "  --max-threads     passed to the started server (its worker pool; default: its own)\n"
    "  --memory-only     start the server without --data-dir (no SQLite)\n"
    "  --server          use a running server instead; --server-pid for memory figures\n"
    "  --admin-key-file  the admin key that server needs for CreateSession\n"
    "  --deadline-seconds  of one call, its retries after RESOURCE_EXHAUSTED included\n"
    "  --max-attempts    of one call, the first included (default: what the deadline allows)\n"
    "  --json            print one JSON object instead of the text report\n"
    "  --soak-rounds     a soak instead: R rounds of S sessions under load for --seconds\n"
    "                    (or --cycles), each ended by deleting them and --rest-seconds of\n"
    "                    rest, with the server's RSS sampled every second; --csv and --png\n"
    "                    write the samples and their plot; --max-rested-growth-mib fails the\n"
    "                    run (exit 1) when RSS after the last rest exceeds the baseline by more\n"
    "  Progress goes to standard error, one line per second. Exit status: 0 when every\n"
    "  session completed, 1 when one failed, 2 for bad flags or a failed set-up.\n";

[[noreturn]] void Usage(const std::string& problem) {
  tools::ExitWithError(kProgram, problem + "\n" + std::string(kUsage));
}

// A whole number in [minimum, maximum] or Usage.
std::int64_t Whole(std::string_view flag, const char* text, std::int64_t minimum,
                   std::int64_t maximum) {
  const std::optional<long long> value = tools::ParseWholeNumber(text, minimum, maximum);
  if (!value) {
    Usage(std::string(flag) + " expects a whole number from " + std::to_string(minimum) + " to " +
          std::to_string(maximum) + ", got '" + text + "'");
  }
  return *value;
}

// Any 64-bit unsigned number (a double would round seeds above 2^53).
std::uint64_t Seed(const char* text) {
  char* end = nullptr;
  errno = 0;
  const unsigned long long seed = std::strtoull(text, &end, 10);
  if (end == text || *end != '\0' || errno == ERANGE || text[0] == '-') {
    Usage(std::string("--seed expects a whole number from 0 to 2^64-1, got '") + text + "'");
  }
  return seed;
}

void ParseSize(const std::string& text, LoadOptions& options) {
  const auto x = text.find('x');
  if (x == std::string::npos) Usage("--synthetic expects WxH, got '" + text + "'");
  options.synthetic_width =
      static_cast<std::uint32_t>(Whole("--synthetic width", text.substr(0, x).c_str(), 16, 4096));
  options.synthetic_height =
      static_cast<std::uint32_t>(Whole("--synthetic height", text.substr(x + 1).c_str(), 16, 4096));
}

}  // namespace

LoadOptions ParseLoadOptions(int argc, char** argv, const std::string& default_server_binary) {
  LoadOptions options;
  options.server_binary = default_server_binary;
  bool cycles_given = false;
  bool synthetic_given = false;
  for (int i = 1; i < argc; ++i) {
    const std::string_view flag = argv[i];
    if (flag == "--help" || flag == "-h") {
      std::fputs(kUsage.data(), stdout);
      std::exit(0);
    }
    if (flag == "--json") {
      options.json = true;
      continue;
    }
    if (flag == "--memory-only") {
      options.memory_only = true;
      continue;
    }
    if (i + 1 >= argc) Usage("bad argument '" + std::string(flag) + "'");
    const char* value = argv[++i];
    if (flag == "--sessions") {
      options.sessions = static_cast<int>(Whole(flag, value, 1, 100000));
    } else if (flag == "--cycles") {
      options.cycles = static_cast<std::uint64_t>(Whole(flag, value, 1, 1000000000));
      cycles_given = true;
    } else if (flag == "--seconds") {
      options.seconds = tools::ParseNumberOrExit(kProgram, flag, value);
      if (!(options.seconds > 0)) Usage("--seconds must be positive");
    } else if (flag == "--seed") {
      options.seed = Seed(value);
    } else if (flag == "--synthetic") {
      ParseSize(value, options);
      synthetic_given = true;
    } else if (flag == "--cloud") {
      options.cloud_path = value;
    } else if (flag == "--server-binary") {
      options.server_binary = value;
    } else if (flag == "--max-threads") {
      options.server_max_threads = static_cast<int>(Whole(flag, value, 2, 100000));
    } else if (flag == "--server") {
      options.server_address = value;
    } else if (flag == "--server-pid") {
      options.server_pid = static_cast<pid_t>(Whole(flag, value, 1, 1 << 30));
    } else if (flag == "--admin-key-file") {
      options.admin_key_file = value;
    } else if (flag == "--max-attempts") {
      options.max_attempts = static_cast<int>(Whole(flag, value, 1, 1000000));
    } else if (flag == "--soak-rounds") {
      options.soak_rounds = static_cast<int>(Whole(flag, value, 1, 100000));
    } else if (flag == "--rest-seconds") {
      options.rest_seconds = tools::ParseNumberOrExit(kProgram, flag, value);
      if (!(options.rest_seconds >= 0)) Usage("--rest-seconds must be 0 or more");
    } else if (flag == "--csv") {
      options.csv_path = value;
    } else if (flag == "--png") {
      options.png_path = value;
    } else if (flag == "--max-rested-growth-mib") {
      options.max_rested_growth_mib = tools::ParseNumberOrExit(kProgram, flag, value);
      if (!(options.max_rested_growth_mib >= 0)) Usage("--max-rested-growth-mib must be 0 or more");
    } else if (flag == "--deadline-seconds") {
      options.deadline_seconds = tools::ParseNumberOrExit(kProgram, flag, value);
      if (!(options.deadline_seconds > 0)) Usage("--deadline-seconds must be positive");
    } else {
      Usage("unknown flag '" + std::string(flag) + "'");
    }
  }
  if (options.seconds > 0 && !cycles_given) options.cycles = 0;
  if (synthetic_given && !options.cloud_path.empty())
    Usage("--synthetic and --cloud exclude each other");
  if (options.soak_rounds == 0 && (!options.csv_path.empty() || !options.png_path.empty() ||
                                   options.max_rested_growth_mib >= 0)) {
    Usage("--csv, --png and --max-rested-growth-mib go with --soak-rounds");
  }
  if (options.server_address.empty() && options.server_pid != 0) {
    Usage("--server-pid goes with --server");
  }
  if (!options.server_address.empty() && (options.server_max_threads != 0 || options.memory_only)) {
    Usage("--max-threads and --memory-only are for a server relmap-load starts, not --server");
  }
  return options;
}

}  // namespace relmap::load
