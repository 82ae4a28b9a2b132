// Parsing and the usage text, in one place so that they agree.
#include "cli_arguments.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "common/command_line.h"

namespace relmap::client {
namespace {

// Flags every command takes: where the server is and how to reach it.
constexpr const char* kGlobalFlags[] = {"server", "token", "admin-key", "tls-ca", "deadline-ms"};

}  // namespace

const char kCliUsage[] =
    "usage: relmap <command> [flags]\n"
    "  session create [--variant corrected|corrected_v1|paper2018] [--alpha A] [--seed S]\n"
    "                 [--feature-dimension P] [--colour corrected|paper2018]\n"
    "                 [--fpfh shared_voxels|exact_union|raw_points] [--fpfh-radius M]\n"
    "                 [--config config.json]\n"
    "  session list\n"
    "  session show   <session>\n"
    "  session delete <session>\n"
    "  session export <session> [--out state.json|state.pb]\n"
    "  session import <state.json|state.pb>\n"
    "  maps    <session> <cloud.pcd> [--png relevance.png] [--choice-png choice.png]\n"
    "          [--pcd coloured.pcd]\n"
    "  outcome <session> <frame> <supervoxel> moved|still [--request-id R]\n"
    "  outcome <session> <frame> <supervoxel> --after-cloud after.pcd [--request-id R]\n"
    "  stream  <session> <samples.csv> [--batch 500]\n"
    "  health  [--service NAME]   grpc.health.v1 Check of the server (NAME empty);\n"
    "          exit 0 only when SERVING (a draining server answers NOT_SERVING)\n"
    "Flags of every command:\n"
    "  --server host:port  (default $RELMAP_SERVER, else 127.0.0.1:50051)\n"
    "  --token T           the session's token (default $RELMAP_TOKEN)\n"
    "  --admin-key K       for create, list, delete, import (default $RELMAP_ADMIN_KEY)\n"
    "  --tls-ca ca.pem     TLS, trusting this CA (default $RELMAP_TLS_CA; else plaintext)\n"
    "  --deadline-ms D     per call, retries included (default 30000)\n"
    "Answers print as JSON (protobuf's JSON mapping, as grpcurl prints them). Exit codes:\n"
    "0 success, 1 the server's error status, 2 bad arguments or files.\n";

void UsageError(const std::string& message) {
  std::fprintf(stderr, "relmap: %s\n%s", message.c_str(), kCliUsage);
  std::exit(2);
}

CommandLine::CommandLine(int argc, char** argv, int first) {
  for (int i = first; i < argc; ++i) {
    const std::string word = argv[i];
    if (word.rfind("--", 0) != 0) {
      positional_.push_back(word);
      continue;
    }
    if (i + 1 >= argc) UsageError(word + " needs a value");
    flags_[word.substr(2)] = argv[++i];
  }
}

void CommandLine::Expect(std::initializer_list<const char*> allowed,
                         std::size_t max_positional) const {
  for (const auto& entry : flags_) {
    // A named reference, not a structured binding: clang before 16 (clang-tidy's
    // parser here) cannot capture a binding in a lambda.
    const std::string& flag = entry.first;
    const auto is = [&](const char* name) { return flag == name; };
    if (std::none_of(allowed.begin(), allowed.end(), is) &&
        std::none_of(std::begin(kGlobalFlags), std::end(kGlobalFlags), is)) {
      UsageError("unknown flag --" + flag);
    }
  }
  if (positional_.size() > max_positional) {
    UsageError("unexpected argument '" + positional_[max_positional] + "'");
  }
}

const std::string& CommandLine::Positional(std::size_t index, const char* name) const {
  if (index >= positional_.size()) UsageError(std::string("missing <") + name + ">");
  return positional_[index];
}

std::string CommandLine::Get(const std::string& flag, const char* environment,
                             const std::string& fallback) const {
  if (const auto it = flags_.find(flag); it != flags_.end()) return it->second;
  if (environment != nullptr) {
    if (const char* value = std::getenv(environment); value != nullptr && *value != '\0') {
      return value;
    }
  }
  return fallback;
}

std::string CommandLine::Required(const std::string& flag, const char* environment) const {
  std::string value = Get(flag, environment);
  if (value.empty()) {
    UsageError("--" + flag + " is required" +
               (environment ? std::string(" (or $") + environment + ")" : std::string()));
  }
  return value;
}

double CommandLine::Number(const std::string& flag) const {
  return tools::ParseNumberOrExit("relmap", "--" + flag, Required(flag).c_str());
}

}  // namespace relmap::client
