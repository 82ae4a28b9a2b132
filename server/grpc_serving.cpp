// The ServerBuilder's settings, each with the reason it is set.
#include "grpc_serving.h"

#include <grpcpp/ext/proto_server_reflection_plugin.h>
#include <grpcpp/health_check_service_interface.h>
#include <grpcpp/resource_quota.h>

#include <fstream>
#include <iterator>
#include <string>

#include "common/command_line.h"
#include "grpc/health/v1/health.pb.h"
#include "relmap/v1/relevance_service.grpc.pb.h"

namespace relmap::server {
namespace {

// The whole of a small file (a certificate or key), or ExitWithError.
std::string ReadFileOrExit(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) tools::ExitWithError("relmap-server", "cannot read " + path);
  if (text.empty()) tools::ExitWithError("relmap-server", path + " is empty or unreadable");
  return text;
}

std::shared_ptr<grpc::ServerCredentials> CredentialsOf(const ServerOptions& options) {
  if (options.tls_cert.empty()) return grpc::InsecureServerCredentials();
  grpc::SslServerCredentialsOptions tls;
  tls.pem_key_cert_pairs.push_back(
      {ReadFileOrExit(options.tls_key), ReadFileOrExit(options.tls_cert)});
  return grpc::SslServerCredentials(tls);
}

}  // namespace

StatusOr<Serving> StartServing(const ServerOptions& options, int threads, grpc::Service& service) {
  grpc::EnableDefaultHealthCheckService(true);
  // Links health.proto's descriptors into the generated pool that reflection reads
  // (gRPC's own health service does not register them, grpc/grpc#36665).
  (void)grpc::health::v1::HealthCheckRequest::descriptor();
  // Without this call Debian's --as-needed link silently drops reflection.
  grpc::reflection::InitProtoReflectionServerBuilderPlugin();
  grpc::ServerBuilder builder;
  Serving serving;
  builder.AddListeningPort(options.listen, CredentialsOf(options), &serving.port);
  // A bounded pool of worker threads: when every thread is busy, gRPC answers new
  // calls with RESOURCE_EXHAUSTED instead of queueing them without bound.
  serving.quota = std::make_unique<grpc::ResourceQuota>("relmap-server");
  serving.quota->SetMaxThreads(threads);
  builder.SetResourceQuota(*serving.quota);
  builder.SetMaxReceiveMessageSize(options.max_message_mb << 20);
  builder.SetMaxSendMessageSize(options.max_message_mb << 20);
  builder.RegisterService(&service);
  serving.server = builder.BuildAndStart();
  if (!serving.server || serving.port == 0) {
    return Status(StatusCode::kUnavailable, "cannot listen on " + options.listen);
  }
  // Probes may ask for the whole server ("") or for the service by name.
  serving.server->GetHealthCheckService()->SetServingStatus(
      v1::RelevanceService::service_full_name(), true);
  return serving;
}

}  // namespace relmap::server
