// relmap session create|list|show|delete|export|import.
#include <google/protobuf/util/json_util.h>

#include <cctype>

#include "cli_commands.h"
#include "common/command_line.h"

namespace relmap::client {
namespace {

bool EndsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The proto enum value named PREFIX + upper(--flag's value): the CLI's names are the API's
// ("raw_points" is FPFH_SCHEME_RAW_POINTS). UNSPECIFIED is not a choice.
template <typename Enum>
Enum EnumFlag(const CommandLine& args, const std::string& flag, const std::string& prefix,
              bool (*parse)(const std::string&, Enum*), const std::string& choices) {
  std::string name = args.Get(flag);
  for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  Enum value{};
  if (name == "UNSPECIFIED" || !parse(prefix + name, &value)) {
    UsageError("--" + flag + " is " + choices + ", not '" + args.Get(flag) + "'");
  }
  return value;
}

// --config (a SessionConfig in JSON) first, then the single-value flags over it.
v1::SessionConfig ConfigFrom(const CommandLine& args) {
  v1::SessionConfig config;
  if (args.Has("config")) {
    const auto parsed =
        google::protobuf::util::JsonStringToMessage(ReadFileOrExit(args.Get("config")), &config);
    if (!parsed.ok()) {
      tools::ExitWithError("relmap", args.Get("config") + ": " + parsed.ToString());
    }
  }
  if (args.Has("variant")) {
    config.mutable_classifier()->set_variant(EnumFlag(args, "variant", "CLASSIFIER_VARIANT_",
                                                      &v1::ClassifierVariant_Parse,
                                                      "corrected, corrected_v1 or paper2018"));
  }
  if (args.Has("alpha")) config.mutable_classifier()->set_alpha(args.Number("alpha"));
  v1::FeatureConfig* features = config.mutable_features();
  if (args.Has("colour")) {
    features->set_colour(EnumFlag(args, "colour", "COLOUR_VARIANT_", &v1::ColourVariant_Parse,
                                  "corrected or paper2018"));
  }
  if (args.Has("fpfh")) {
    features->set_fpfh_scheme(EnumFlag(args, "fpfh", "FPFH_SCHEME_", &v1::FpfhScheme_Parse,
                                       "shared_voxels, exact_union or raw_points"));
  }
  if (args.Has("fpfh-radius")) {
    features->set_fpfh_radius(static_cast<float>(args.Number("fpfh-radius")));
  }
  if (args.Has("seed")) config.set_seed(static_cast<std::uint64_t>(args.Number("seed")));
  if (args.Has("feature-dimension")) {
    config.set_feature_dimension(static_cast<std::uint32_t>(args.Number("feature-dimension")));
  }
  return config;
}

// Session state files: JSON when the name ends in .json (readable, exact: protobuf
// prints doubles with 17 digits), the binary protobuf encoding otherwise.
void WriteState(const std::string& path, const v1::SessionState& state) {
  std::string bytes;
  if (EndsWith(path, ".json")) {
    (void)google::protobuf::util::MessageToJsonString(state, &bytes);
  } else {
    state.SerializeToString(&bytes);
  }
  WriteFileOrExit(path, bytes);
}

v1::SessionState ReadState(const std::string& path) {
  const std::string bytes = ReadFileOrExit(path);
  v1::SessionState state;
  const bool parsed = EndsWith(path, ".json")
                          ? google::protobuf::util::JsonStringToMessage(bytes, &state).ok()
                          : state.ParseFromString(bytes);
  if (!parsed) tools::ExitWithError("relmap", path + " is not a relmap session state");
  return state;
}

}  // namespace

int RunSessionCommand(const std::string& verb, const CommandLine& args) {
  const std::unique_ptr<RelevanceClient> client = ClientFrom(args);
  if (verb == "create") {
    args.Expect({"variant", "alpha", "seed", "feature-dimension", "colour", "fpfh", "fpfh-radius",
                 "config"},
                0);
    SessionHandle created;
    v1::CreateSessionResponse response;
    return PrintAnswer(client->CreateSession(ConfigFrom(args), &created, &response), response);
  }
  if (verb == "list") {
    args.Expect({}, 0);
    v1::ListSessionsResponse response;
    return PrintAnswer(client->ListSessions(&response), response);
  }
  if (verb == "show") {
    args.Expect({}, 1);
    v1::GetSessionResponse response;
    return PrintAnswer(client->GetSession(SessionFrom(args, 0), &response), response);
  }
  if (verb == "delete") {
    args.Expect({}, 1);
    return PrintAnswer(client->DeleteSession(SessionFrom(args, 0)), v1::DeleteSessionResponse{});
  }
  if (verb == "export") {
    args.Expect({"out"}, 1);
    v1::ExportSessionResponse response;
    const grpc::Status status = client->ExportSession(SessionFrom(args, 0), &response);
    if (!status.ok() || !args.Has("out")) return PrintAnswer(status, response);
    WriteState(args.Get("out"), response.state());
    return PrintAnswer(status, response.stats());
  }
  if (verb == "import") {
    args.Expect({}, 1);
    SessionHandle imported;
    v1::ImportSessionResponse response;
    return PrintAnswer(
        client->ImportSession(ReadState(args.Positional(0, "state file")), &imported, &response),
        response);
  }
  UsageError("unknown command 'session " + verb + "'");
}

}  // namespace relmap::client
