// relmap-dataset: writes a seeded toy problem as labelled CSV, the demo and
// test streams of relmap-cmm.
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <string_view>

#include "common/command_line.h"
#include "common/labelled_csv.h"
#include "datasets/synthetic_problems.h"

namespace {

constexpr std::string_view kUsage =
    "usage: relmap-dataset --problem moons|xor|rings [--samples 1000] [--dimension 2]\n"
    "                      [--noise 0.1] [--ambient-noise 0.02] [--seed 1] [--embedding-seed 0]\n"
    "  Writes label,f1,...,fp rows to standard output.\n";

[[noreturn]] void Fail(const std::string& message) {
  relmap::tools::ExitWithError("relmap-dataset", message + "\n" + std::string(kUsage));
}

double Number(std::string_view flag, const char* text) {
  return relmap::tools::ParseNumberOrExit("relmap-dataset", flag, text);
}

int Main(int argc, char** argv) {
  using namespace relmap::datasets;
  ProblemOptions options;
  for (int i = 1; i < argc; ++i) {
    const std::string_view flag = argv[i];
    if (flag == "--help" || flag == "-h") {
      std::fputs(kUsage.data(), stdout);
      return 0;
    }
    if (i + 1 >= argc) Fail(std::string(flag) + " needs a value");
    const char* value = argv[++i];
    if (flag == "--problem") {
      const auto problem = ParseProblem(value);
      if (!problem.ok()) Fail(problem.status().message());
      options.problem = *problem;
    } else if (flag == "--samples") {
      options.samples = static_cast<int>(Number(flag, value));
    } else if (flag == "--dimension") {
      options.dimension = static_cast<int>(Number(flag, value));
    } else if (flag == "--noise") {
      options.noise = Number(flag, value);
    } else if (flag == "--ambient-noise") {
      options.ambient_noise = Number(flag, value);
    } else if (flag == "--seed") {
      options.seed = static_cast<std::uint64_t>(Number(flag, value));
    } else if (flag == "--embedding-seed") {
      options.embedding_seed = static_cast<std::uint64_t>(Number(flag, value));
    } else {
      Fail("unknown argument '" + std::string(flag) + "'");
    }
  }
  if (options.samples < 1 || options.dimension < 2) Fail("--samples >= 1 and --dimension >= 2");
  WriteLabelledCsv(MakeProblem(options), std::cout);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return relmap::tools::ExitCodeOf("relmap-dataset", [&] { return Main(argc, argv); });
}
