// relmap: the command-line client. Every command prints the server's answer as
// JSON (protobuf's JSON mapping, the same as grpcurl's) and exits 0, or prints
// the gRPC status and exits 1; bad arguments exit 2.
#include <google/protobuf/util/json_util.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <string_view>

#include "relevance_client.h"
#include "tools/command_line.h"

namespace {

using relmap::tools::ExitWithError;

constexpr std::string_view kUsage =
    "usage: relmap <command> [--server host:port] [flags]\n"
    "  create  [--variant corrected|paper2018] [--alpha A] [--seed S] [--feature-dimension P]\n"
    "  get     --session ID --token T\n"
    "  list\n"
    "  delete  --session ID --token T\n"
    "  maps    --session ID --token T --cloud file.pcd\n"
    "  post    --session ID --token T --frame F --supervoxel S\n"
    "          (--label moveable|not-moveable | --after-cloud after.pcd) [--request-id R]\n"
    "  --server defaults to $RELMAP_SERVER or 127.0.0.1:50051; --session and --token to\n"
    "  $RELMAP_SESSION and $RELMAP_TOKEN; --admin-key (create, list, delete) to\n"
    "  $RELMAP_ADMIN_KEY.\n";

[[noreturn]] void Usage(const std::string& message) {
  ExitWithError("relmap", message + "\n" + std::string(kUsage));
}

std::string FromEnvironment(const char* name, std::string fallback) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? value : fallback;
}

int Print(const grpc::Status& status, const google::protobuf::Message& response) {
  if (!status.ok()) {
    std::fprintf(stderr, "relmap: %s: %s\n",
                 status.error_code() == grpc::StatusCode::UNAVAILABLE ? "UNAVAILABLE" : "error",
                 status.error_message().c_str());
    std::fprintf(stderr, "relmap: gRPC status code %d\n", static_cast<int>(status.error_code()));
    return 1;
  }
  std::string json;
  google::protobuf::util::JsonPrintOptions options;
  options.always_print_primitive_fields = true;
  (void)google::protobuf::util::MessageToJsonString(response, &json, options);
  std::printf("%s\n", json.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace relmap;
  if (argc < 2 || std::string_view(argv[1]) == "--help") {
    std::fputs(kUsage.data(), argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  const std::string command = argv[1];
  std::map<std::string, std::string> flags;
  for (int i = 2; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag.rfind("--", 0) != 0 || i + 1 >= argc) Usage("bad argument '" + flag + "'");
    flags[flag.substr(2)] = argv[++i];
  }
  const auto flag = [&](const std::string& name, std::string fallback = "") {
    const auto it = flags.find(name);
    return it == flags.end() ? fallback : it->second;
  };
  const auto required = [&](const std::string& name, const char* environment = nullptr) {
    std::string value = flag(name, environment ? FromEnvironment(environment, "") : "");
    if (value.empty()) Usage("--" + name + " is required for '" + command + "'");
    return value;
  };
  const auto number = [&](const std::string& name) {
    return tools::ParseNumberOrExit("relmap", "--" + name, required(name).c_str());
  };

  client::RelevanceClient relevance(
      flag("server", FromEnvironment("RELMAP_SERVER", "127.0.0.1:50051")));
  relevance.set_admin_key(flag("admin-key", FromEnvironment("RELMAP_ADMIN_KEY", "")));
  const auto session = [&] {
    return client::SessionHandle{required("session", "RELMAP_SESSION"),
                                 required("token", "RELMAP_TOKEN")};
  };

  if (command == "create") {
    v1::SessionConfig config;
    const std::string variant = flag("variant", "corrected");
    if (variant != "corrected" && variant != "paper2018")
      Usage("unknown variant '" + variant + "'");
    config.mutable_classifier()->set_variant(variant == "paper2018"
                                                 ? v1::CLASSIFIER_VARIANT_PAPER2018
                                                 : v1::CLASSIFIER_VARIANT_CORRECTED);
    if (flags.count("alpha")) config.mutable_classifier()->set_alpha(number("alpha"));
    if (flags.count("seed")) config.set_seed(static_cast<std::uint64_t>(number("seed")));
    if (flags.count("feature-dimension")) {
      config.set_feature_dimension(static_cast<std::uint32_t>(number("feature-dimension")));
    }
    client::SessionHandle created;
    v1::CreateSessionResponse response;
    return Print(relevance.CreateSession(config, &created, &response), response);
  }
  if (command == "get") {
    v1::GetSessionResponse response;
    return Print(relevance.GetSession(session(), &response), response);
  }
  if (command == "list") {
    v1::ListSessionsResponse response;
    return Print(relevance.ListSessions(&response), response);
  }
  if (command == "delete") {
    return Print(relevance.DeleteSession(session()), v1::DeleteSessionResponse{});
  }
  const auto read_cloud = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) ExitWithError("relmap", "cannot open " + path);
    return client::PcdCloud(
        std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()));
  };
  if (command == "maps") {
    const client::SessionHandle handle = session();
    v1::ComputeMapsResponse response;
    const grpc::Status status =
        relevance.ComputeMaps(handle, read_cloud(required("cloud")), &response);
    response.clear_point_labels();  // one per pixel: too long for a terminal
    return Print(status, response);
  }
  if (command == "post" && flags.count("after-cloud")) {
    v1::PostOutcomeResponse response;
    return Print(
        relevance.PostOutcome(session(), static_cast<std::uint64_t>(number("frame")),
                              static_cast<std::uint32_t>(number("supervoxel")),
                              read_cloud(flag("after-cloud")), flag("request-id"), &response),
        response);
  }
  if (command == "post") {
    const std::string label = required("label");
    if (label != "moveable" && label != "not-moveable")
      Usage("--label is moveable or not-moveable");
    v1::PostOutcomeResponse response;
    return Print(
        relevance.PostOutcome(session(), static_cast<std::uint64_t>(number("frame")),
                              static_cast<std::uint32_t>(number("supervoxel")),
                              label == "moveable" ? v1::LABEL_MOVEABLE : v1::LABEL_NOT_MOVEABLE,
                              flag("request-id"), &response),
        response);
  }
  Usage("unknown command '" + command + "'");
}
