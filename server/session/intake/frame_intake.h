// The clouds a server takes in: a bounded admission (frame_admission.h), then the
// decoding of the bytes a client uploaded. The edge hands over bytes and gets back a
// cloud to process, or why not.
#pragma once

#include <chrono>
#include <cstdint>
#include <string_view>

#include "common/status.h"
#include "perception/cloud.h"
#include "perception/perception_config.h"
#include "session/intake/frame_admission.h"

namespace relmap::session {

// An uploaded cloud as its client encoded it, not yet decoded. The bytes belong to
// the caller and must outlive the call that takes them.
struct EncodedCloud {
  enum class Format { kMissing, kPcd, kPacked };
  Format format = Format::kMissing;
  std::string_view bytes;
  std::uint32_t width = 0;  // of the packed layout
  std::uint32_t height = 0;
};

// A decoded cloud and the processing slot it holds until it is destroyed.
struct AdmittedCloud {
  FrameAdmission::Ticket slot;
  perception::Cloud cloud;
  std::chrono::steady_clock::time_point admitted_at;
  std::chrono::steady_clock::time_point decoded_at;
};

// The longest a frame waits for its turn by default: longer than one round-robin turn
// of hundreds of sessions (docs/reliability.md, "Fairness under load").
inline constexpr std::chrono::milliseconds kDefaultMaxFrameWait{60000};

struct FrameIntakeLimits {
  perception::DecodeLimits decode;
  // Clouds processed at once, clouds waiting, and the longest wait.
  std::size_t concurrent = 2;
  std::size_t queued = 4;
  std::chrono::milliseconds max_wait = kDefaultMaxFrameWait;
};

class FrameIntake {
 public:
  explicit FrameIntake(const FrameIntakeLimits& limits)
      : decode_limits_(limits.decode),
        max_wait_(limits.max_wait),
        admission_(limits.concurrent, limits.queued) {}

  // What Take gives back. `busy`: no slot came before the deadline, nothing ran, and
  // `cloud` holds RESOURCE_EXHAUSTED; the call may be repeated as it is.
  // How long a client turned away as busy should wait before it repeats the call.
  static constexpr int kBusyRetryAfterMs = 100;

  struct Taken {
    StatusOr<AdmittedCloud> cloud;
    bool busy = false;
  };

  // A slot, waiting at most until `deadline` or the limits' max_wait in the turn of
  // `session` (frame_admission.h), then the decoded cloud; a cloud that does not
  // decode keeps its decoder's status.
  Taken Take(const EncodedCloud& encoded, std::chrono::system_clock::time_point deadline,
             std::string_view session = {});

  FrameAdmission& admission() { return admission_; }

 private:
  StatusOr<perception::Cloud> Decode(const EncodedCloud& encoded) const;

  const perception::DecodeLimits decode_limits_;
  const std::chrono::milliseconds max_wait_;
  FrameAdmission admission_;
};

}  // namespace relmap::session
