// CreateSession and DeleteSession for every session of a run.
#include "load_sessions.h"

#include <cstdio>

namespace relmap::load {

StatusOr<std::vector<LoadSession>> CreateLoadSessions(client::RelevanceClient& client, int count,
                                                      Random& seeds) {
  std::vector<LoadSession> sessions(static_cast<std::size_t>(count));
  for (LoadSession& session : sessions) {
    session.seed = seeds.NextBits();
    v1::SessionConfig config;
    config.set_seed(session.seed);
    if (const grpc::Status status = client.CreateSession(config, &session.handle); !status.ok()) {
      DeleteLoadSessions(client, sessions);
      return Status(static_cast<StatusCode>(status.error_code()),
                    "CreateSession: " + status.error_message());
    }
  }
  return sessions;
}

void DeleteLoadSessions(client::RelevanceClient& client, const std::vector<LoadSession>& sessions) {
  for (const LoadSession& session : sessions) {
    if (session.handle.id.empty()) continue;
    if (const grpc::Status status = client.DeleteSession(session.handle); !status.ok()) {
      std::fprintf(stderr, "relmap-load: DeleteSession %s: %s\n", session.handle.id.c_str(),
                   status.error_message().c_str());
    }
  }
}

}  // namespace relmap::load
