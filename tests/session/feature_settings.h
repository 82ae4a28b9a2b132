// Settings of a session fed with raw feature vectors, not clouds: small, and learned
// in microseconds, for tests of the session layer and of what sits on it.
#pragma once

#include "session/session_settings.h"

namespace relmap::session::testing {

inline constexpr int kTestFeatureDimension = 3;

inline SessionSettings FeatureSettings() {
  SessionSettings settings;
  settings.feature_dimension = kTestFeatureDimension;
  return settings;
}

}  // namespace relmap::session::testing
