// The handlers: authorise, translate the request, call the session layer,
// translate the answer or its status.
#include "service/relevance_service.h"

#include <algorithm>
#include <chrono>

#include "service/call_log.h"
#include "service/config_mapping.h"
#include "service/status_mapping.h"
#include "session/session_listing.h"

namespace relmap::service {
namespace {

std::int64_t NowUnixMs() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// The label of the API as the classifier's 0/1; -1 if unset.
int ClassOf(v1::Label label) {
  switch (label) {
    case v1::LABEL_MOVEABLE:
      return 1;
    case v1::LABEL_NOT_MOVEABLE:
      return 0;
    default:
      return -1;
  }
}

v1::Vector3 ToProto(const Eigen::Vector3f& v) {
  v1::Vector3 out;
  out.set_x(v.x()), out.set_y(v.y()), out.set_z(v.z());
  return out;
}

// Feature vectors of a request as the rows of a matrix; ragged →
// INVALID_ARGUMENT.
StatusOr<Eigen::MatrixXd> FeatureRows(
    const google::protobuf::RepeatedPtrField<v1::FeatureVector>& rows) {
  if (rows.empty()) return InvalidArgumentError("the request has no feature vector");
  const int p = rows[0].values_size();
  Eigen::MatrixXd matrix(rows.size(), p);
  for (int i = 0; i < rows.size(); ++i) {
    if (rows[i].values_size() != p) {
      return InvalidArgumentError("feature vector " + std::to_string(i) + " has " +
                                  std::to_string(rows[i].values_size()) + " values, vector 0 has " +
                                  std::to_string(p));
    }
    for (int k = 0; k < p; ++k) matrix(i, k) = rows[i].values(k);
  }
  return matrix;
}

struct LabelledRows {
  Eigen::MatrixXd features;
  std::vector<int> labels;  // -1 where the label is unset
};

// Labelled feature vectors of a request; ragged → INVALID_ARGUMENT.
StatusOr<LabelledRows> LabelledRowsOf(
    const google::protobuf::RepeatedPtrField<v1::LabelledFeature>& samples) {
  google::protobuf::RepeatedPtrField<v1::FeatureVector> vectors;
  LabelledRows rows;
  for (const v1::LabelledFeature& sample : samples) {
    *vectors.Add() = sample.feature();
    rows.labels.push_back(ClassOf(sample.label()));
  }
  auto features = FeatureRows(vectors);
  if (!features.ok()) return features.status();
  rows.features = std::move(features).value();
  return rows;
}

}  // namespace

Status RelevanceService::CheckFeatureCount(int count) const {
  if (static_cast<std::size_t>(count) <= max_features_per_request_) return OkStatus();
  return ResourceExhaustedError("the request carries " + std::to_string(count) +
                                " feature vectors; this server takes at most " +
                                std::to_string(max_features_per_request_) + " per request");
}

StatusOr<session::AdmittedCloud> RelevanceService::TakeCloud(grpc::ServerContext& context,
                                                             const v1::Cloud& cloud) {
  session::FrameIntake::Taken taken = intake_.Take(EncodedCloudOf(cloud), context.deadline());
  // gRPC's server pushback trailer (retry design A6): the call did nothing, repeat it
  // after this long. relmap's client reads it; gRPC's own retry policy would too.
  if (taken.busy) context.AddTrailingMetadata("grpc-retry-pushback-ms", "100");
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
    auto settings = SettingsFromProto(request->config());
    if (!settings.ok()) return ToGrpcStatus(settings.status());
    // The store keeps the filled-in config, from which a restart rebuilds the
    // settings.
    const std::string config_blob = ProtoFromSettings(*settings).SerializeAsString();
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
      entry->set_session_id(session->id());
      *entry->mutable_config() = ProtoFromSettings(session->settings());
      FillStats(session->Stats(), entry->mutable_stats());
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
    auto cloud = TakeCloud(*context, request->cloud());
    if (!cloud.ok()) return ToGrpcStatus(cloud.status());
    const auto milliseconds = [](auto from, auto to) {
      return std::chrono::duration<double, std::milli>(to - from).count();
    };
    const double admission_ms = milliseconds(start, cloud->admitted_at);
    const double decode_ms = milliseconds(cloud->admitted_at, cloud->decoded_at);
    auto mapped = (*session)->ComputeMaps(std::move(cloud->cloud), NowUnixMs());
    if (!mapped.ok()) return ToGrpcStatus(mapped.status());

    const perception::Frame& frame = *mapped->frame;
    const exploration::FrameMaps& maps = mapped->maps;
    response->set_frame_id(mapped->frame_id);
    for (const perception::Supervoxel& sv : frame.segmentation.supervoxels) {
      v1::Supervoxel* out = response->add_supervoxels();
      out->set_id(sv.id);
      *out->mutable_centroid() = ToProto(sv.centroid);
      *out->mutable_normal() = ToProto(sv.normal);
      out->set_point_count(static_cast<std::uint32_t>(sv.point_indices.size()));
      out->set_relevance(maps.relevance[sv.id]);
      out->set_choice(maps.choice[sv.id]);
      if (request->include_features()) {
        const auto row = frame.features.values.row(sv.id);
        out->mutable_features()->Add(row.begin(), row.end());
      }
    }
    if (maps.target >= 0)
      response->set_target_supervoxel_id(static_cast<std::uint32_t>(maps.target));
    if (!request->omit_point_labels()) {
      response->mutable_point_labels()->Add(frame.segmentation.point_labels.begin(),
                                            frame.segmentation.point_labels.end());
    }
    response->set_unusable_supervoxels(static_cast<std::uint32_t>(maps.unusable_rows));
    v1::StageTimings* timings = response->mutable_timings();
    timings->set_admission_ms(admission_ms);
    timings->set_decode_ms(decode_ms);
    timings->set_filter_ms(frame.timings.filter_ms);
    timings->set_supervoxels_ms(frame.timings.supervoxels_ms);
    timings->set_features_ms(frame.timings.features_ms);
    timings->set_maps_ms(mapped->maps_ms);
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
    StatusOr<session::Outcome> outcome = InvalidArgumentError(
        "the outcome needs a label (LABEL_MOVEABLE or "
        "LABEL_NOT_MOVEABLE) or an after_cloud");
    if (request->has_after_cloud()) {
      auto after = TakeCloud(*context, request->after_cloud());
      if (!after.ok()) return ToGrpcStatus(after.status());
      outcome = (*session)->PostOutcomeFromCloud(request->frame_id(), request->supervoxel_id(),
                                                 std::move(after->cloud), request->request_id(),
                                                 NowUnixMs());
    } else if (const int label = ClassOf(request->label()); label >= 0) {
      outcome = (*session)->PostOutcome(request->frame_id(), request->supervoxel_id(), label,
                                        request->request_id(), NowUnixMs());
    }
    if (!outcome.ok()) return ToGrpcStatus(outcome.status());
    response->set_label(outcome->label == 1 ? v1::LABEL_MOVEABLE : v1::LABEL_NOT_MOVEABLE);
    FillStats(outcome->stats, response->mutable_stats());
    if (outcome->evidence) FillEvidence(*outcome->evidence, response->mutable_evidence());
    return grpc::Status::OK;
  });
}

grpc::Status RelevanceService::ClassifyFeatures(grpc::ServerContext* context,
                                                const v1::ClassifyFeaturesRequest* request,
                                                v1::ClassifyFeaturesResponse* response) {
  return Logged(metrics_, "ClassifyFeatures", request->session_id(), [&] {
    auto session = Authorised(*context, request->session_id());
    if (!session.ok()) return ToGrpcStatus(session.status());
    if (Status limit = CheckFeatureCount(request->features_size()); !limit.ok()) {
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
    if (Status limit = CheckFeatureCount(request->samples_size()); !limit.ok()) {
      return ToGrpcStatus(limit);
    }
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
    const session::SessionState state = (*session)->ExportState();
    v1::SessionState* out = response->mutable_state();
    *out->mutable_config() = ProtoFromSettings((*session)->settings());
    for (Eigen::Index i = 0; i < state.features.rows(); ++i) {
      v1::LabelledFeature* sample = out->add_samples();
      for (Eigen::Index k = 0; k < state.features.cols(); ++k) {
        sample->mutable_feature()->add_values(state.features(i, k));
      }
      sample->set_label(state.labels[static_cast<std::size_t>(i)] == 1 ? v1::LABEL_MOVEABLE
                                                                       : v1::LABEL_NOT_MOVEABLE);
    }
    out->mutable_target_rng_state()->Add(state.target_random.begin(), state.target_random.end());
    out->set_interactions(state.interactions);
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
    const v1::SessionState& in = request->state();
    if (in.target_rng_state_size() != 4) {
      return grpc::Status(grpc::StatusCode::INVALID_ARGUMENT,
                          "state.target_rng_state must hold the 4 words of the RNG");
    }
    if (Status limit = CheckFeatureCount(in.samples_size()); !limit.ok())
      return ToGrpcStatus(limit);
    session::SessionState state;
    if (in.samples_size() > 0) {
      auto rows = LabelledRowsOf(in.samples());
      if (!rows.ok()) return ToGrpcStatus(rows.status());
      state.features = std::move(rows->features);
      state.labels = std::move(rows->labels);
    }
    std::copy(in.target_rng_state().begin(), in.target_rng_state().end(),
              state.target_random.begin());
    state.interactions = in.interactions();

    auto settings = SettingsFromProto(in.config());
    if (!settings.ok()) return ToGrpcStatus(settings.status());
    const std::string config_blob = ProtoFromSettings(*settings).SerializeAsString();
    auto created = registry_.Create(std::move(settings).value(), config_blob, NowUnixMs());
    if (!created.ok()) return ToGrpcStatus(created.status());
    id = created->session->id();
    auto stats = created->session->ImportState(state, NowUnixMs());
    if (!stats.ok()) {
      (void)registry_.Delete(id);  // no half-imported session stays behind
      return ToGrpcStatus(stats.status());
    }
    response->set_session_id(id);
    response->set_session_token(created->token);
    FillStats(*stats, response->mutable_stats());
    registry_.HandOver(id);
    return grpc::Status::OK;
  });
}

}  // namespace relmap::service
