// One place that checks a session's settings.
#include "session/session_settings.h"

#include <string>

namespace relmap::session {

Status Validate(const SessionSettings& settings) {
  if (Status s = cmm::Validate(settings.classifier); !s.ok()) return s;
  if (Status s = perception::Validate(settings.perception); !s.ok()) return s;
  if (settings.feature_dimension < 1 || settings.feature_dimension > 4096) {
    return InvalidArgumentError("feature dimension must lie in [1, 4096], got " +
                                std::to_string(settings.feature_dimension));
  }
  return OkStatus();
}

}  // namespace relmap::session
