// Loading a stored session: record, settings, snapshot, samples, counters.
#include "session/registry/session_restore.h"

#include <spdlog/spdlog.h>

#include <chrono>

namespace relmap::session {

StatusOr<SessionSettings> StoredSessionSettings(const SessionRecord& record,
                                                const StoredSettingsDecoder& decode_settings) {
  auto settings = decode_settings(record);
  if (!settings.ok()) return settings.status();
  // A session stored as "corrected" before December 2026 was migrated to
  // corrected_v1 there, while its config message still says CORRECTED.
  if (record.cmm_config.variant != settings->classifier.variant) {
    settings->exploration = exploration::ExplorationConfig::ForVariant(record.cmm_config.variant);
  }
  settings->classifier = record.cmm_config;
  return settings;
}

StatusOr<std::shared_ptr<Session>> LoadStoredSession(SessionStore& store, const std::string& id,
                                                     const StoredSettingsDecoder& decode_settings) {
  const auto start = std::chrono::steady_clock::now();
  auto record = store.LoadSession(id);
  if (!record.ok()) return record.status();
  auto settings = StoredSessionSettings(*record, decode_settings);
  if (!settings.ok()) return settings.status();
  const std::int64_t created_ms = UnixMilliseconds(record->created_at);
  auto loaded = Session::Create(record->id, record->token_hash, std::move(settings).value(),
                                created_ms, &store);
  if (!loaded.ok()) return loaded.status();
  // The latest snapshot, if any, then the samples after it.
  auto snapshot = store.LoadLatestSnapshot(id);
  if (!snapshot.ok()) return snapshot.status();
  std::int64_t from_snapshot = 0;
  if (snapshot->has_value()) {
    if (Status status = (*loaded)->RestoreModel((*snapshot)->snapshot); !status.ok()) {
      return status;
    }
    from_snapshot = (*snapshot)->sample_count;
  }
  auto samples = store.LoadSamples(id);
  if (!samples.ok()) return samples.status();
  (*loaded)->RestoreCounters(static_cast<std::uint64_t>(record->counters.frames_computed),
                             static_cast<std::uint64_t>(record->counters.interactions));
  (*loaded)->RestoreLastUsed(UnixMilliseconds(record->last_used));
  if (Status status = (*loaded)->Replay(*samples); !status.ok()) return status;
  // Fills the summary of a session stored before summaries existed, or one whose
  // last summary was lost in a crash (not in another server's session: fenced).
  (*loaded)->RecordSummary();
  spdlog::info(
      "restored session={} samples={} (snapshot of {}) in {:.1f} ms", id, samples->size(),
      from_snapshot,
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  return std::shared_ptr<Session>(std::move(loaded).value());
}

}  // namespace relmap::session
