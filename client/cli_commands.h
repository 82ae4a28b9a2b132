// The relmap CLI's commands, one function each, and what they share: the client
// built from the flags, the session named on the command line, JSON answers.
#pragma once

#include <google/protobuf/message.h>
#include <grpcpp/grpcpp.h>

#include <cstddef>
#include <memory>
#include <string>

#include "cli_arguments.h"
#include "relevance_client.h"

namespace relmap::client {

// Each returns the process's exit code: 0, 1 for a server error, 2 for bad input.
int RunSessionCommand(const std::string& verb, const CommandLine& args);
int RunMaps(const CommandLine& args);
int RunOutcome(const CommandLine& args);
int RunStream(const CommandLine& args);
// 0 when the server reports SERVING, 1 otherwise (NOT_SERVING, or no answer).
int RunHealth(const CommandLine& args);

// A client configured from the global flags (and their environment variables).
std::unique_ptr<RelevanceClient> ClientFrom(const CommandLine& args);
// Positional word `index` as the session id, with the token of --token/$RELMAP_TOKEN.
SessionHandle SessionFrom(const CommandLine& args, std::size_t index);

// The answer as one line of JSON on stdout and 0, or the status on stderr and 1.
int PrintAnswer(const grpc::Status& status, const google::protobuf::Message& answer);
// The whole file, or exit 2 naming it.
std::string ReadFileOrExit(const std::string& path);
// Writes `bytes` to `path`, or exits 2 naming it.
void WriteFileOrExit(const std::string& path, const std::string& bytes);

}  // namespace relmap::client
