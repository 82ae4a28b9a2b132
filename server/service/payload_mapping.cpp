// Feature vectors are copied value by value: the API's rows are repeated doubles, the
// session's an Eigen matrix, and a ragged request must be refused, not padded.
#include "service/payload_mapping.h"

#include <algorithm>
#include <string>

namespace relmap::service {
namespace {

v1::Vector3 ToProto(const Eigen::Vector3f& v) {
  v1::Vector3 out;
  out.set_x(v.x()), out.set_y(v.y()), out.set_z(v.z());
  return out;
}

}  // namespace

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

v1::Label LabelOf(int label) { return label == 1 ? v1::LABEL_MOVEABLE : v1::LABEL_NOT_MOVEABLE; }

Status CheckFeatureCount(int count, std::size_t max) {
  if (static_cast<std::size_t>(count) <= max) return OkStatus();
  return ResourceExhaustedError("the request carries " + std::to_string(count) +
                                " feature vectors; this server takes at most " +
                                std::to_string(max) + " per request");
}

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

void FillMappedFrame(const session::MappedFrame& mapped, bool include_features,
                     bool omit_point_labels, v1::ComputeMapsResponse* out) {
  const perception::Frame& frame = *mapped.frame;
  const exploration::FrameMaps& maps = mapped.maps;
  out->set_frame_id(mapped.frame_id);
  for (const perception::Supervoxel& sv : frame.segmentation.supervoxels) {
    v1::Supervoxel* supervoxel = out->add_supervoxels();
    supervoxel->set_id(sv.id);
    *supervoxel->mutable_centroid() = ToProto(sv.centroid);
    *supervoxel->mutable_normal() = ToProto(sv.normal);
    supervoxel->set_point_count(static_cast<std::uint32_t>(sv.point_indices.size()));
    supervoxel->set_relevance(maps.relevance[sv.id]);
    supervoxel->set_choice(maps.choice[sv.id]);
    supervoxel->set_object(frame.objects[sv.id]);
    if (include_features) {
      const auto row = frame.features.values.row(sv.id);
      supervoxel->mutable_features()->Add(row.begin(), row.end());
    }
  }
  if (maps.target >= 0) out->set_target_supervoxel_id(static_cast<std::uint32_t>(maps.target));
  if (!omit_point_labels) {
    out->mutable_point_labels()->Add(frame.segmentation.point_labels.begin(),
                                     frame.segmentation.point_labels.end());
  }
  out->set_unusable_supervoxels(static_cast<std::uint32_t>(maps.unusable_rows));
  v1::StageTimings* timings = out->mutable_timings();
  timings->set_filter_ms(frame.timings.filter_ms);
  timings->set_supervoxels_ms(frame.timings.supervoxels_ms);
  timings->set_features_ms(frame.timings.features_ms);
  timings->set_maps_ms(mapped.maps_ms);
}

void FillState(const session::SessionState& state, v1::SessionState* out) {
  for (Eigen::Index i = 0; i < state.features.rows(); ++i) {
    v1::LabelledFeature* sample = out->add_samples();
    for (Eigen::Index k = 0; k < state.features.cols(); ++k) {
      sample->mutable_feature()->add_values(state.features(i, k));
    }
    sample->set_label(LabelOf(state.labels[static_cast<std::size_t>(i)]));
  }
  out->mutable_target_rng_state()->Add(state.target_random.begin(), state.target_random.end());
  out->set_interactions(state.interactions);
}

StatusOr<session::SessionState> StateFromProto(const v1::SessionState& in,
                                               std::size_t max_features) {
  if (in.target_rng_state_size() != 4) {
    return InvalidArgumentError("state.target_rng_state must hold the 4 words of the RNG");
  }
  if (Status limit = CheckFeatureCount(in.samples_size(), max_features); !limit.ok()) return limit;
  session::SessionState state;
  if (in.samples_size() > 0) {
    auto rows = LabelledRowsOf(in.samples());
    if (!rows.ok()) return rows.status();
    state.features = std::move(rows->features);
    state.labels = std::move(rows->labels);
  }
  std::copy(in.target_rng_state().begin(), in.target_rng_state().end(),
            state.target_random.begin());
  state.interactions = in.interactions();
  return state;
}

}  // namespace relmap::service
