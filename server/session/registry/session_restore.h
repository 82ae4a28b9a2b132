// A stored session back in memory: the settings from its stored record, the model
// from its latest snapshot plus the samples after it (the same model, bit for bit,
// as before the restart or eviction).
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "common/status.h"
#include "session/records/session_record.h"
#include "session/session.h"
#include "session/session_settings.h"
#include "session/store/session_store.h"

namespace relmap::session {

// The settings a stored record's `config` asks for. The layer that wrote the blob
// reads it back (the service: the API's SessionConfig); the store keeps it opaque.
using StoredSettingsDecoder = std::function<StatusOr<SessionSettings>(const SessionRecord&)>;

// The settings of a stored session: its record's `config` as `decode_settings` reads
// it, with the classifier as the store recorded it field by field.
StatusOr<SessionSettings> StoredSessionSettings(const SessionRecord& record,
                                                const StoredSettingsDecoder& decode_settings);

// NOT_FOUND for an id the store does not hold; DATA_LOSS when its record,
// snapshot or samples do not decode.
StatusOr<std::shared_ptr<Session>> LoadStoredSession(SessionStore& store, const std::string& id,
                                                     const StoredSettingsDecoder& decode_settings);

}  // namespace relmap::session
