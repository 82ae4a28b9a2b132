// Translation between the API's messages and the session layer's types.
#pragma once

#include <string>

#include "common/status.h"
#include "perception/change_detector.h"
#include "relmap/v1/relevance_service.pb.h"
#include "session/intake/frame_intake.h"
#include "session/records/session_record.h"
#include "session/session.h"
#include "session/session_settings.h"

namespace relmap::service {

// The classifier variant of the API's enum; a value outside it (an old or a
// corrupt client) → INVALID_ARGUMENT naming the field, not a silent default.
StatusOr<cmm::Variant> VariantFromProto(int variant);
v1::ClassifierVariant VariantToProto(cmm::Variant variant);

// The settings a SessionConfig asks for, unset fields at their defaults; the
// ranges are checked by session::Validate when the session is created.
StatusOr<session::SessionSettings> SettingsFromProto(const v1::SessionConfig& config);

// The SessionConfig of `settings`, every default filled in.
v1::SessionConfig ProtoFromSettings(const session::SessionSettings& settings);

void FillStats(const session::SessionStats& stats, v1::SessionStats* out);

void FillEvidence(const perception::ChangeEvidence& evidence, v1::ChangeEvidence* out);

// A request's cloud as session::FrameIntake takes it; the bytes stay `cloud`'s.
session::EncodedCloud EncodedCloudOf(const v1::Cloud& cloud);

// What the store keeps of `settings` (SessionRegistry::Create's config blob): their
// SessionConfig, every default filled in, serialised.
std::string StoredConfigOf(const session::SessionSettings& settings);

// The settings of a stored session, from the SessionConfig that CreateSession
// stored (session::StoredSettingsDecoder); DATA_LOSS when it does not parse.
StatusOr<session::SessionSettings> SettingsOfStoredSession(const session::SessionRecord& record);

}  // namespace relmap::service
