// relmap health: the server's grpc.health.v1 status, for container health checks,
// probes and scripts (grpc_health_probe is not a Debian package).
#include "cli_commands.h"

namespace relmap::client {

int RunHealth(const CommandLine& args) {
  args.Expect({"service"}, 0);
  const std::unique_ptr<RelevanceClient> client = ClientFrom(args);
  grpc::health::v1::HealthCheckResponse response;
  if (PrintAnswer(client->CheckHealth(args.Get("service"), &response), response) != 0) return 1;
  return response.status() == grpc::health::v1::HealthCheckResponse::SERVING ? 0 : 1;
}

}  // namespace relmap::client
