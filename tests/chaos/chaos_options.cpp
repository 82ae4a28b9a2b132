// Flags of relmap-chaos, each checked against its range.
#include "chaos/chaos_options.h"

#include <cstdio>
#include <optional>
#include <string_view>

#include "common/command_line.h"

namespace relmap::chaos {
namespace {

constexpr std::string_view kProgram = "relmap-chaos";
constexpr std::string_view kUsage =
    "usage: relmap-chaos [--store sqlite|postgres|cluster|memory] [--cycles 20] [--sessions 8]\n"
    "                    [--writes-per-cycle 3] [--samples-per-batch 4] [--seed 1]\n"
    "                    [--synthetic 160x120] [--server-binary PATH] [--directory DIR]\n"
    "  kill -9 of a relmap-server, --cycles times, while --sessions sessions (one thread\n"
    "  each) loop ComputeMaps, PostOutcome and AddSamples with request ids, repeating each\n"
    "  write with its id until the server answers; the server restarts on the same store.\n"
    "  At the end every server is killed and restarted once more, and each session's\n"
    "  exported samples are checked against what the server acknowledged.\n"
    "  --store       sqlite: one server on its SQLite file; postgres: one server on a\n"
    "                throw-away PostgreSQL; cluster: two servers on it behind nginx, the\n"
    "                cycles killing the one serving a session caught mid-write;\n"
    "                memory: one server without a store, which loses everything at a\n"
    "                restart (the check's negative control: the run must fail)\n"
    "  --writes-per-cycle  writes every session has acknowledged between two kills\n"
    "  --directory   keep the store and the logs there (default: a temporary directory,\n"
    "                removed unless something was lost)\n"
    "  Exit status: 0 when nothing acknowledged was lost or duplicated, 1 when something\n"
    "  was (or a session stopped), 2 for bad flags or a failed set-up, 77 when the store\n"
    "  asked for cannot run here (no PostgreSQL or nginx).\n";

[[noreturn]] void Usage(const std::string& problem) {
  tools::ExitWithError(kProgram, problem + "\n" + std::string(kUsage));
}

// A whole number in [minimum, maximum] or Usage.
long long WholeInRange(std::string_view flag, const char* text, long long minimum,
                       long long maximum) {
  const std::optional<long long> value = tools::ParseWholeNumber(text, minimum, maximum);
  if (!value) {
    Usage(std::string(flag) + " expects a whole number in [" + std::to_string(minimum) + ", " +
          std::to_string(maximum) + "], got '" + text + "'");
  }
  return *value;
}

StoreKind StoreNamed(const std::string& name) {
  if (name == "sqlite") return StoreKind::kSqlite;
  if (name == "postgres") return StoreKind::kPostgres;
  if (name == "cluster") return StoreKind::kCluster;
  if (name == "memory") return StoreKind::kMemory;
  Usage("--store expects sqlite, postgres, cluster or memory, got '" + name + "'");
}

}  // namespace

ChaosOptions ParseChaosOptions(int argc, char** argv, const std::string& default_server_binary) {
  ChaosOptions options;
  options.server_binary = default_server_binary;
  for (int i = 1; i < argc; ++i) {
    const std::string_view flag = argv[i];
    if (flag == "--help" || flag == "-h") {
      std::fputs(kUsage.data(), stdout);
      std::exit(0);
    }
    if (i + 1 >= argc) Usage("bad argument '" + std::string(flag) + "'");
    const char* value = argv[++i];
    if (flag == "--store") {
      options.store = StoreNamed(value);
    } else if (flag == "--cycles") {
      options.cycles = static_cast<int>(WholeInRange(flag, value, 0, 100000));
    } else if (flag == "--sessions") {
      options.sessions = static_cast<int>(WholeInRange(flag, value, 1, 256));
    } else if (flag == "--writes-per-cycle") {
      options.writes_per_cycle = static_cast<int>(WholeInRange(flag, value, 1, 100000));
    } else if (flag == "--samples-per-batch") {
      options.samples_per_batch = static_cast<int>(WholeInRange(flag, value, 1, 1000));
    } else if (flag == "--seed") {
      options.seed = static_cast<std::uint64_t>(WholeInRange(flag, value, 0, 1LL << 52));
    } else if (flag == "--synthetic") {
      const std::string size = value;
      const auto x = size.find('x');
      if (x == std::string::npos) Usage("--synthetic expects WxH, got '" + size + "'");
      options.cloud_width = static_cast<std::uint32_t>(
          WholeInRange("--synthetic width", size.substr(0, x).c_str(), 16, 640));
      options.cloud_height = static_cast<std::uint32_t>(
          WholeInRange("--synthetic height", size.substr(x + 1).c_str(), 16, 480));
    } else if (flag == "--server-binary") {
      options.server_binary = value;
    } else if (flag == "--directory") {
      options.directory = value;
    } else {
      Usage("unknown flag '" + std::string(flag) + "'");
    }
  }
  return options;
}

}  // namespace relmap::chaos
