// Admission before decoding: a decode is itself work a busy server must not start.
#include "session/intake/frame_intake.h"

#include <algorithm>
#include <string>

#include "perception/decode.h"

namespace relmap::session {

FrameIntake::Taken FrameIntake::Take(const EncodedCloud& encoded,
                                     std::chrono::system_clock::time_point deadline,
                                     std::string_view session) {
  std::optional<FrameAdmission::Ticket> slot =
      admission_.Enter(std::min(deadline, std::chrono::system_clock::now() + max_wait_), session);
  if (!slot) {
    // The reason BUSY says to clients what the service's pushback trailer says to gRPC.
    return {
        ResourceExhaustedError(
            "busy: " + std::to_string(admission_.running()) + " clouds in progress and " +
            std::to_string(admission_.waiting()) +
            " waiting (--max-concurrent-frames, --max-queued-frames); retry later")
            .WithReason(ErrorReason::kBusy, {{"retryAfterMs", std::to_string(kBusyRetryAfterMs)}}),
        true};
  }
  const auto admitted_at = std::chrono::steady_clock::now();
  auto cloud = Decode(encoded);
  if (!cloud.ok()) return {cloud.status()};
  return {AdmittedCloud{std::move(*slot), std::move(cloud).value(), admitted_at,
                        std::chrono::steady_clock::now()}};
}

StatusOr<perception::Cloud> FrameIntake::Decode(const EncodedCloud& encoded) const {
  switch (encoded.format) {
    case EncodedCloud::Format::kPcd:
      return perception::DecodePcd(encoded.bytes, decode_limits_);
    case EncodedCloud::Format::kPacked:
      return perception::DecodePacked(encoded.bytes, encoded.width, encoded.height, decode_limits_);
    case EncodedCloud::Format::kMissing:
      break;
  }
  // The API's field names: the client reads this message.
  return InvalidArgumentError("the request carries no cloud (set cloud.pcd or cloud.packed)");
}

}  // namespace relmap::session
