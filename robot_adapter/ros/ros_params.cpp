// Parameters are read as XmlRpc values and their types checked here, because
// NodeHandle::param silently falls back to the default on a type mismatch.
#include "ros_params.h"

#include <fstream>
#include <sstream>

namespace relmap::ros_bridge {
namespace {

class ParamReader {
 public:
  explicit ParamReader(const ros::NodeHandle& node) : node_(node) {}

  void Read(const std::string& name, std::string* out) {
    XmlRpc::XmlRpcValue value;
    if (!Fetch(name, &value)) return;
    if (value.getType() != XmlRpc::XmlRpcValue::TypeString) return Wrong(name, "a string");
    *out = static_cast<std::string>(value);
  }
  void Read(const std::string& name, bool* out) {
    XmlRpc::XmlRpcValue value;
    if (!Fetch(name, &value)) return;
    if (value.getType() != XmlRpc::XmlRpcValue::TypeBoolean) return Wrong(name, "true or false");
    *out = static_cast<bool>(value);
  }
  void Read(const std::string& name, int* out) {
    XmlRpc::XmlRpcValue value;
    if (!Fetch(name, &value)) return;
    if (value.getType() != XmlRpc::XmlRpcValue::TypeInt) return Wrong(name, "an integer");
    *out = static_cast<int>(value);
  }
  // Integers are accepted as doubles: `seed: 1.0` is a mistake, `period: 1` is not.
  void Read(const std::string& name, double* out) {
    XmlRpc::XmlRpcValue value;
    if (!Fetch(name, &value)) return;
    if (value.getType() == XmlRpc::XmlRpcValue::TypeInt) {
      *out = static_cast<int>(value);
    } else if (value.getType() == XmlRpc::XmlRpcValue::TypeDouble) {
      *out = static_cast<double>(value);
    } else {
      Wrong(name, "a number");
    }
  }
  bool Has(const std::string& name) const { return node_.hasParam(name); }
  const Status& status() const { return status_; }

 private:
  bool Fetch(const std::string& name, XmlRpc::XmlRpcValue* value) {
    return status_.ok() && node_.getParam(name, *value);
  }
  void Wrong(const std::string& name, const char* expected) {
    status_ = InvalidArgumentError("~" + name + " must be " + expected);
  }

  const ros::NodeHandle& node_;
  Status status_;
};

}  // namespace

StatusOr<NodeSettings> ReadNodeSettings(const ros::NodeHandle& private_node) {
  NodeSettings settings;
  BridgeConfig& bridge = settings.bridge;
  ParamReader params(private_node);
  params.Read("server", &bridge.client.address);
  double deadline_seconds = static_cast<double>(bridge.client.deadline.count()) / 1000.0;
  params.Read("deadline_seconds", &deadline_seconds);
  bridge.client.deadline = std::chrono::milliseconds(static_cast<long>(deadline_seconds * 1000));
  std::string certificates_file;
  params.Read("tls_root_certificates", &certificates_file);
  params.Read("admin_key", &bridge.admin_key);
  params.Read("session_id", &bridge.session_id);
  params.Read("session_token", &bridge.session_token);
  int seed = 1;
  params.Read("seed", &seed);
  bridge.session.set_seed(static_cast<std::uint64_t>(seed));
  if (params.Has("workspace")) {
    v1::WorkspaceBox* box = bridge.session.mutable_workspace();
    const char* bounds[] = {"min_x", "max_x", "min_y", "max_y", "min_z", "max_z"};
    double values[6] = {};
    for (int i = 0; i < 6; ++i) {
      if (!params.Has(std::string("workspace/") + bounds[i])) {
        return InvalidArgumentError(std::string("~workspace has no ") + bounds[i] +
                                    ": give all of min_x, max_x, min_y, max_y, min_z, max_z");
      }
      params.Read(std::string("workspace/") + bounds[i], &values[i]);
    }
    box->set_min_x(static_cast<float>(values[0]));
    box->set_max_x(static_cast<float>(values[1]));
    box->set_min_y(static_cast<float>(values[2]));
    box->set_max_y(static_cast<float>(values[3]));
    box->set_min_z(static_cast<float>(values[4]));
    box->set_max_z(static_cast<float>(values[5]));
  }
  params.Read("workspace_frame", &bridge.workspace_frame);
  params.Read("push_loop", &bridge.push_loop);
  params.Read("max_pushes", &bridge.max_pushes);
  params.Read("frames_kept", &bridge.frames_kept);
  params.Read("cloud_topic", &settings.cloud_topic);
  params.Read("after_cloud_topic", &settings.after_cloud_topic);
  params.Read("push_service", &settings.push_service);
  params.Read("tf_timeout_seconds", &settings.tf_timeout_seconds);
  params.Read("diagnostics_period_seconds", &settings.diagnostics_period_seconds);
  params.Read("min_period_seconds", &settings.min_period_seconds);
  params.Read("record_bag", &settings.record_bag);
  if (!params.status().ok()) return params.status();

  if (!certificates_file.empty()) {
    std::ifstream in(certificates_file);
    if (!in) {
      return InvalidArgumentError("~tls_root_certificates: cannot read " + certificates_file);
    }
    std::ostringstream pem;
    pem << in.rdbuf();
    bridge.client.tls_root_certificates = pem.str();
  }
  for (const auto& [name, value] : {std::pair{"tf_timeout_seconds", settings.tf_timeout_seconds},
                                    std::pair{"min_period_seconds", settings.min_period_seconds}}) {
    if (!(value >= 0)) return InvalidArgumentError(std::string("~") + name + " must be 0 or more");
  }
  if (!(settings.diagnostics_period_seconds > 0)) {
    return InvalidArgumentError("~diagnostics_period_seconds must be positive");
  }
  if (settings.cloud_topic.empty() || settings.push_service.empty()) {
    return InvalidArgumentError("~cloud_topic and ~push_service must not be empty");
  }
  bridge.keep_sent_clouds = !settings.record_bag.empty();
  Status valid = ValidateBridgeConfig(bridge);
  if (!valid.ok()) return valid;
  return settings;
}

}  // namespace relmap::ros_bridge
