// The handlers: authorise, translate the request, call the session layer, translate
// the answer or its status.
#include "service/relevance_service.h"

#include <chrono>
#include <span>

#include "service/api_limits.h"
#include "service/call_log.h"
#include "service/config_mapping.h"
#include "service/payload_mapping.h"
#include "service/status_mapping.h"
#include "session/registry/session_listing.h"

namespace relmap::service {
namespace {

std::int64_t NowUnixMs() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace

StatusOr<session::AdmittedCloud> RelevanceService::TakeCloud(grpc::ServerContext& context,
                                                             const v1::Cloud& cloud,
                                                             const std::string& session_id) {
  session::FrameIntake::Taken taken =
      intake_.Take(EncodedCloudOf(cloud), context.deadline(), session_id);
  // gRPC's server pushback trailer (retry design A6): the call did nothing, repeat it
  // after this long. relmap's client reads it; gRPC's own retry policy would too.
  if (taken.busy) {
    context.AddTrailingMetadata("grpc-retry-pushback-ms",
                                std::to_string(session::FrameIntake::kBusyRetryAfterMs));
  }
  return std::move(taken.cloud);
}

std::string RelevanceService::MetricsText() const {
  std::uint64_t samples = 0;
  const auto sessions = registry_.Resident();  // a scrape must not load evicted sessions
  for (const auto& session : sessions) {
    const session::SessionStats stats = session->Stats();
    samples += stats.samples[0] + stats.samples[1];
  }
  return metrics_.PrometheusText(sessions.size(), samples);
}

StatusOr<std::shared_ptr<session::Session>> RelevanceService::Authorised(
    grpc::ServerContext& context, const std::string& id) const {
  auto session = authorization_.SessionFor(CredentialsOf(context), id);
  if (!session.ok() && session.status().code() == StatusCode::kUnavailable) {
    context.AddTrailingMetadata("grpc-retry-pushback-ms", "200");
  }
  return session;
}

grpc::Status RelevanceService::CreateSession(grpc::ServerContext* context,
                                             const v1::CreateSessionRequest* request,
                                             v1::CreateSessionResponse* response) {
  std::string id;
  return Logged(metrics_, "CreateSession", id, [&] {
    if (Status admin = authorization_.Admin(CredentialsOf(*context)); !admin.ok()) {
      return ToGrpcStatus(admin);
    }
    if (Status valid = CheckSessionConfig(request->config(), "config."); !valid.ok()) {
      return ToGrpcStatus(valid);
    }
    auto settings = SettingsFromProto(request->config());
    if (!settings.ok()) return ToGrpcStatus(settings.status());
    // The store keeps the filled-in config, from which a restart rebuilds the settings.
    const std::string config_blob = StoredConfigOf(*settings);
    auto created = registry_.Create(std::move(settings).value(), config_blob, NowUnixMs());
    if (!created.ok()) return ToGrpcStatus(created.status());
    id = created->session->id();
    response->set_session_id(id);
    response->set_session_token(created->token);
    *response->mutable_config() = ProtoFromSettings(created->session->settings());
    registry_.HandOver(id);
    return grpc::Status::OK;
  });
}

grpc::Status RelevanceService::GetSession(grpc::ServerContext* context,
                                          const v1::GetSessionRequest* request,
                                          v1::GetSessionResponse* response) {
  return Logged(metrics_, "GetSession", request->session_id(), [&] {
    auto session = Authorised(*context, request->session_id());
    if (!session.ok()) return ToGrpcStatus(session.status());
    response->set_session_id((*session)->id());
    *response->mutable_config() = ProtoFromSettings((*session)->settings());
    FillStats((*session)->Stats(), response->mutable_stats());
    return grpc::Status::OK;
  });
}

grpc::Status RelevanceService::ListSessions(grpc::ServerContext* context,
                                            const v1::ListSessionsRequest* request,
                                            v1::ListSessionsResponse* response) {
  return Logged(metrics_, "ListSessions", "", [&] {
    if (Status admin = authorization_.Admin(CredentialsOf(*context)); !admin.ok()) {
      return ToGrpcStatus(admin);
    }
    auto page = session::ListSessionPage(registry_, request->page_token(), request->page_size());
    if (!page.ok()) return ToGrpcStatus(page.status());
    response->set_next_page_token(page->next_page_token);
    for (const auto& session : page->sessions) {
      v1::GetSessionResponse* entry = response->add_sessions();
      entry->set_session_id(session.id);
      *entry->mutable_config() = ProtoFromSettings(session.settings);
      FillStats(session.stats, entry->mutable_stats());
    }
    return grpc::Status::OK;
  });
}

grpc::Status RelevanceService::DeleteSession(grpc::ServerContext* context,
                                             const v1::DeleteSessionRequest* request,
                                             v1::DeleteSessionResponse*) {
  return Logged(metrics_, "DeleteSession", request->session_id(), [&] {
    if (Status allowed = authorization_.Deletion(CredentialsOf(*context), request->session_id());
        !allowed.ok()) {
      return ToGrpcStatus(allowed);
    }
    return ToGrpcStatus(registry_.Delete(request->session_id()));
  });
}

grpc::Status RelevanceService::ComputeMaps(grpc::ServerContext* context,
                                           const v1::ComputeMapsRequest* request,
                                           v1::ComputeMapsResponse* response) {
  return Logged(metrics_, "ComputeMaps", request->session_id(), [&] {
    const auto start = std::chrono::steady_clock::now();
    auto session = Authorised(*context, request->session_id());
    if (!session.ok()) return ToGrpcStatus(session.status());
    auto cloud = TakeCloud(*context, request->cloud(), request->session_id());
    if (!cloud.ok()) return ToGrpcStatus(cloud.status());
    const auto milliseconds = [](auto from, auto to) {
      return std::chrono::duration<double, std::milli>(to - from).count();
    };
    const double admission_ms = milliseconds(start, cloud->admitted_at);
    const double decode_ms = milliseconds(cloud->admitted_at, cloud->decoded_at);
    auto mapped = (*session)->ComputeMaps(std::move(cloud->cloud), NowUnixMs());
    if (!mapped.ok()) return ToGrpcStatus(mapped.status());

    FillMappedFrame(*mapped, request->include_features(), request->omit_point_labels(), response);
    v1::StageTimings* timings = response->mutable_timings();
    timings->set_admission_ms(admission_ms);
    timings->set_decode_ms(decode_ms);
    timings->set_total_ms(milliseconds(start, std::chrono::steady_clock::now()));
    return grpc::Status::OK;
  });
}

grpc::Status RelevanceService::PostOutcome(grpc::ServerContext* context,
                                           const v1::PostOutcomeRequest* request,
                                           v1::PostOutcomeResponse* response) {
  return Logged(metrics_, "PostOutcome", request->session_id(), [&] {
    auto session = Authorised(*context, request->session_id());
    if (!session.ok()) return ToGrpcStatus(session.status());
    if (Status valid = CheckEnumValues(*request); !valid.ok()) return ToGrpcStatus(valid);
    const session::Alongside alongside{
        {request->moved_supervoxels().data(),
         static_cast<std::size_t>(request->moved_supervoxels().size())},
        {request->object_supervoxels().data(),
         static_cast<std::size_t>(request->object_supervoxels().size())}};
    StatusOr<session::Outcome> outcome = InvalidArgumentError(
        "the outcome needs a label (LABEL_MOVEABLE or LABEL_NOT_MOVEABLE) or an after_cloud");
    if (request->has_after_cloud()) {
      auto after = TakeCloud(*context, request->after_cloud(), request->session_id());
      if (!after.ok()) return ToGrpcStatus(after.status());
      outcome = (*session)->PostOutcomeFromCloud(request->frame_id(), request->supervoxel_id(),
                                                 after->cloud, request->request_id(), NowUnixMs(),
                                                 alongside);
    } else if (const int label = ClassOf(request->label()); label >= 0) {
      outcome = (*session)->PostOutcome(request->frame_id(), request->supervoxel_id(), label,
                                        request->request_id(), NowUnixMs(), alongside);
    }
    if (!outcome.ok()) return ToGrpcStatus(outcome.status());
    response->set_label(LabelOf(outcome->label));
    FillStats(outcome->stats, response->mutable_stats());
    if (outcome->evidence) FillEvidence(*outcome->evidence, response->mutable_evidence());
    response->set_moved_learned(outcome->moved_learned);
    response->set_object_learned(outcome->object_learned);
    return grpc::Status::OK;
  });
}

grpc::Status RelevanceService::ClassifyFeatures(grpc::ServerContext* context,
                                                const v1::ClassifyFeaturesRequest* request,
                                                v1::ClassifyFeaturesResponse* response) {
  return Logged(metrics_, "ClassifyFeatures", request->session_id(), [&] {
    auto session = Authorised(*context, request->session_id());
    if (!session.ok()) return ToGrpcStatus(session.status());
    if (Status limit = CheckFeatureCount(request->features_size(), max_features_per_request_);
        !limit.ok()) {
      return ToGrpcStatus(limit);
    }
    auto rows = FeatureRows(request->features());
    if (!rows.ok()) return ToGrpcStatus(rows.status());
    auto maps = (*session)->ClassifyFeatures(*rows, NowUnixMs());
    if (!maps.ok()) return ToGrpcStatus(maps.status());
    response->mutable_relevance()->Add(maps->relevance.data(),
                                       maps->relevance.data() + maps->relevance.size());
    response->mutable_choice()->Add(maps->choice.data(), maps->choice.data() + maps->choice.size());
    return grpc::Status::OK;
  });
}

grpc::Status RelevanceService::AddSamples(grpc::ServerContext* context,
                                          const v1::AddSamplesRequest* request,
                                          v1::AddSamplesResponse* response) {
  return Logged(metrics_, "AddSamples", request->session_id(), [&] {
    auto session = Authorised(*context, request->session_id());
    if (!session.ok()) return ToGrpcStatus(session.status());
    if (Status limit = CheckFeatureCount(request->samples_size(), max_features_per_request_);
        !limit.ok()) {
      return ToGrpcStatus(limit);
    }
    if (Status valid = CheckEnumValues(*request); !valid.ok()) return ToGrpcStatus(valid);
    auto rows = LabelledRowsOf(request->samples());
    if (!rows.ok()) return ToGrpcStatus(rows.status());
    auto stats =
        (*session)->AddSamples(rows->features, rows->labels, request->request_id(), NowUnixMs());
    if (!stats.ok()) return ToGrpcStatus(stats.status());
    FillStats(*stats, response->mutable_stats());
    return grpc::Status::OK;
  });
}

grpc::Status RelevanceService::ExportSession(grpc::ServerContext* context,
                                             const v1::ExportSessionRequest* request,
                                             v1::ExportSessionResponse* response) {
  return Logged(metrics_, "ExportSession", request->session_id(), [&] {
    auto session = Authorised(*context, request->session_id());
    if (!session.ok()) return ToGrpcStatus(session.status());
    *response->mutable_state()->mutable_config() = ProtoFromSettings((*session)->settings());
    FillState((*session)->ExportState(), response->mutable_state());
    FillStats((*session)->Stats(), response->mutable_stats());
    return grpc::Status::OK;
  });
}

grpc::Status RelevanceService::ImportSession(grpc::ServerContext* context,
                                             const v1::ImportSessionRequest* request,
                                             v1::ImportSessionResponse* response) {
  std::string id;
  return Logged(metrics_, "ImportSession", id, [&] {
    if (Status admin = authorization_.Admin(CredentialsOf(*context)); !admin.ok()) {
      return ToGrpcStatus(admin);
    }
    if (Status limit =
            CheckFeatureCount(request->state().samples_size(), max_features_per_request_);
        !limit.ok()) {
      return ToGrpcStatus(limit);
    }
    if (Status valid = CheckEnumValues(*request); !valid.ok()) return ToGrpcStatus(valid);
    if (Status valid = CheckSessionConfig(request->state().config(), "state.config.");
        !valid.ok()) {
      return ToGrpcStatus(valid);
    }
    auto state = StateFromProto(request->state(), max_features_per_request_);
    if (!state.ok()) return ToGrpcStatus(state.status());
    auto settings = SettingsFromProto(request->state().config());
    if (!settings.ok()) return ToGrpcStatus(settings.status());
    const std::string config_blob = StoredConfigOf(*settings);
    auto created = registry_.Import(std::move(settings).value(), config_blob, *state, NowUnixMs());
    if (!created.ok()) return ToGrpcStatus(created.status());
    id = created->session->id();
    response->set_session_id(id);
    response->set_session_token(created->token);
    FillStats(created->session->Stats(), response->mutable_stats());
    registry_.HandOver(id);
    return grpc::Status::OK;
  });
}

}  // namespace relmap::service
