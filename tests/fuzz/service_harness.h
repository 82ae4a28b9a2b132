// An in-process RelevanceService for the fuzz targets: a fresh registry (memory
// only, no store) and service per input, with limits small enough that one input
// stays cheap. Each RPC's handler is called directly, with a ServerContext whose
// client metadata the harness sets, so no channel or server runs.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace relmap::fuzz {

// The RPCs of RelevanceService, in the proto's order.
enum class Rpc : std::uint8_t {
  kCreateSession,
  kGetSession,
  kListSessions,
  kDeleteSession,
  kComputeMaps,
  kPostOutcome,
  kClassifyFeatures,
  kAddSamples,
  kExportSession,
  kImportSession,
};
inline constexpr int kRpcCount = 10;

// How a call is made around its request.
struct CallSetup {
  // Create a session first from `create_request` (a serialized CreateSessionRequest;
  // unparseable or refused: no session), then...
  bool create_session = false;
  std::string_view create_request;
  // ...map `first_frame` on it (a serialized ComputeMapsRequest; empty: none), then
  // put its id (and that frame's) in the request and its token in the call's metadata.
  std::string_view first_frame;
  bool use_session_id = false;
  bool send_token = false;
};

// Parses `request` as the RPC's request message and calls its handler. Returns
// false when the bytes do not parse (the input is not worth keeping).
bool CallOnce(Rpc rpc, std::string_view request, const CallSetup& setup);

}  // namespace relmap::fuzz
