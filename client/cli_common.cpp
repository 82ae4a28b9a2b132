// What every CLI command shares.
#include <google/protobuf/util/json_util.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iterator>

#include "cli_commands.h"
#include "common/command_line.h"
#include "error_reason.h"

namespace relmap::client {

std::unique_ptr<RelevanceClient> ClientFrom(const CommandLine& args) {
  ClientOptions options;
  options.address = args.Get("server", "RELMAP_SERVER", "127.0.0.1:50051");
  if (args.Has("deadline-ms")) {
    options.deadline =
        std::chrono::milliseconds(static_cast<long long>(args.Number("deadline-ms")));
  }
  if (const std::string ca = args.Get("tls-ca", "RELMAP_TLS_CA"); !ca.empty()) {
    options.tls_root_certificates = ReadFileOrExit(ca);
  }
  auto client = std::make_unique<RelevanceClient>(std::move(options));
  client->set_admin_key(args.Get("admin-key", "RELMAP_ADMIN_KEY"));
  return client;
}

SessionHandle SessionFrom(const CommandLine& args, std::size_t index) {
  return {args.Positional(index, "session"), args.Required("token", "RELMAP_TOKEN")};
}

int PrintAnswer(const grpc::Status& status, const google::protobuf::Message& answer) {
  if (!status.ok()) {
    // The reason too, when there is one: what a script around the CLI decides by.
    const v1::ErrorReason reason = ReasonOf(status);
    const std::string reason_text =
        reason == v1::ERROR_REASON_UNSPECIFIED ? "" : ", reason " + v1::ErrorReason_Name(reason);
    std::fprintf(stderr, "relmap: %s (gRPC status code %d%s)\n", status.error_message().c_str(),
                 static_cast<int>(status.error_code()), reason_text.c_str());
    return 1;
  }
  std::string json;
  google::protobuf::util::JsonPrintOptions options;
  options.always_print_primitive_fields = true;
  (void)google::protobuf::util::MessageToJsonString(answer, &json, options);
  std::printf("%s\n", json.c_str());
  return 0;
}

std::string ReadFileOrExit(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) tools::ExitWithError("relmap", "cannot open " + path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void WriteFileOrExit(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  if (!out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()))) {
    tools::ExitWithError("relmap", "cannot write " + path);
  }
}

}  // namespace relmap::client
