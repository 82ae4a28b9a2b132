// Through std::system and the shell: the script is an optional extra, and a
// failure of it is reported in the table, never fatal.
#include "learning_bench/reference.h"

#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>

#include "learning_bench/table_csv.h"

namespace relmap::learning_bench {
namespace {

// A single-quoted shell word: ' becomes '\''.
std::string ShellQuote(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

ReferenceOutcome RunReference(const std::string& script, const std::string& streams_dir,
                              const std::string& out_csv, std::uint64_t seed) {
  if (!std::filesystem::exists(script)) return {{}, "not run: no script " + script};
  // The python3 on PATH first; then the system's, where Debian's python3-sklearn
  // lives when PATH leads to another installation (pyenv, a virtualenv).
  std::string python;
  for (const char* candidate : {"python3", "/usr/bin/python3"}) {
    const std::string probe = fmt::format("{} -c 'import sklearn' >/dev/null 2>&1", candidate);
    if (std::system(probe.c_str()) == 0) {
      python = candidate;
      break;
    }
  }
  if (python.empty()) return {{}, "not run: no python3 with sklearn"};
  const std::string command =
      fmt::format("{} {} --streams {} --out {} --seed {} 1>&2", python, ShellQuote(script),
                  ShellQuote(streams_dir), ShellQuote(out_csv), seed);
  if (std::system(command.c_str()) != 0) return {{}, "not run: the script failed"};
  auto rows = ReadTableCsv(out_csv);
  if (!rows.ok()) return {{}, "not run: " + rows.status().message()};
  return {std::move(rows).value(), "run"};
}

}  // namespace relmap::learning_bench
