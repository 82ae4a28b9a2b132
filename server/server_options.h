// relmap-server's settings: flags, a --config file (lines "name value") and
// RELMAP_<NAME> environment variables, in decreasing precedence, checked in one place.
#pragma once

#include <cstddef>
#include <string>

#include "session/intake/frame_intake.h"

namespace relmap::server {

// The most frames a session may keep: each holds its cloud's supervoxels and features.
inline constexpr std::size_t kMaxFramesPerSession = 256;
// The longest a frame may wait for a processing slot: ten minutes, past any client's
// patience, so that a mistyped setting cannot park worker threads for days.
inline constexpr long long kMaxFrameWaitMs = 600000;

struct ServerOptions {
  std::string listen = "127.0.0.1:50051";
  int max_message_mb = 64;
  std::size_t max_sessions = 1000;
  long long max_points = 1280LL * 960LL;
  std::string port_file;
  std::string data_dir;
  // Where sessions persist: "sqlite:PATH" (one server) or a "postgres://…" URI (a
  // database that several servers share); --data-dir DIR means sqlite:DIR/relmap.sqlite.
  std::string store;
  // With PostgreSQL: how long a server's hold on a session outlives its last call.
  long long lease_seconds = 10;
  // On SIGTERM: report NOT_SERVING this long before refusing calls, so that load
  // balancers move traffic away first.
  long long drain_seconds = 0;
  std::string admin_key;
  std::string tls_cert;
  std::string tls_key;
  int max_threads = 0;  // 0: sized from the sessions in memory (worker_sizing.h)
  std::size_t snapshot_every = 500;
  // Also a snapshot once the samples since the last took this long to learn (0: never).
  long long snapshot_after_learning_ms = 500;
  long long evict_idle_seconds = 1800;
  // Sessions unused this long are deleted, from memory and from the store (0: never).
  long long session_idle_expiry_seconds = 0;
  std::size_t max_features_per_request = 100000;
  std::size_t frames_per_session = 8;
  // Calls that process a cloud: running at once (default: the machine's cores) and
  // waiting for a slot, beyond which they are refused (session/intake/frame_admission.h).
  std::size_t max_concurrent_frames = 0;  // 0: std::thread::hardware_concurrency()
  // 0: half of max_threads when that is given, else sized from the sessions.
  std::size_t max_queued_frames = 0;
  // The longest a call waits in that queue before it is refused; its client's deadline
  // ends it sooner. Longer than one round-robin turn of all sessions, or a refused call
  // loses its place and waits the turn again (docs/reliability.md, "Fairness").
  long long max_frame_wait_ms = session::kDefaultMaxFrameWait.count();
  std::string metrics_listen;
  std::string metrics_port_file;
};

// The settings of this process; --help prints the usage and exits 0, a bad or
// unknown setting exits 2 with a message.
ServerOptions ParseServerOptions(int argc, char** argv);

}  // namespace relmap::server
