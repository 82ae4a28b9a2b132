// Replays stored samples; the service layer owns it because the stored settings
// are the API's SessionConfig message.
#include "service/session_restore.h"

#include <spdlog/spdlog.h>

#include <chrono>

#include "service/config_mapping.h"

namespace relmap::service {

Status RestoreSessions(session::SessionStore& store, session::SessionRegistry& registry) {
  auto summaries = store.ListSessions();
  if (!summaries.ok()) return summaries.status();
  for (const session::SessionSummary& summary : *summaries) {
    const auto start = std::chrono::steady_clock::now();
    auto record = store.LoadSession(summary.id);
    if (!record.ok()) return record.status();
    v1::SessionConfig config;
    if (!config.ParseFromString(record->config)) {
      return DataLossError("session " + summary.id + ": its stored configuration does not parse");
    }
    auto settings = SettingsFromProto(config);
    if (!settings.ok()) return settings.status();
    const std::int64_t created_ms =
        std::chrono::duration_cast<std::chrono::milliseconds>(record->created_at.time_since_epoch())
            .count();
    auto restored = session::Session::Create(record->id, record->token_hash,
                                             std::move(settings).value(), created_ms, &store);
    if (!restored.ok()) return restored.status();
    // The latest snapshot, if any, then the samples after it.
    auto snapshot = store.LoadLatestSnapshot(summary.id);
    if (!snapshot.ok()) return snapshot.status();
    std::int64_t from_snapshot = 0;
    if (snapshot->has_value()) {
      if (Status status = (*restored)->RestoreModel((*snapshot)->snapshot); !status.ok()) {
        return status;
      }
      from_snapshot = (*snapshot)->sample_count;
    }
    auto samples = store.LoadSamples(summary.id);
    if (!samples.ok()) return samples.status();
    if (Status status = (*restored)->Replay(*samples); !status.ok()) return status;
    if (Status status = registry.Adopt(std::move(restored).value()); !status.ok()) return status;
    spdlog::info("restored session={} samples={} (snapshot of {}) in {:.1f} ms", summary.id,
                 samples->size(), from_snapshot,
                 std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                     .count());
  }
  return OkStatus();
}

}  // namespace relmap::service
