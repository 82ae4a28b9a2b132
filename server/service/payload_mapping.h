// Translation of the calls' payloads between the API's messages and the session
// layer's values: feature vectors and labels, a mapped frame, a session's state.
// (The session's config has its own file, config_mapping.h.)
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "common/status.h"
#include "relmap/v1/relevance_service.pb.h"
#include "session/session.h"

namespace relmap::service {

// The label of the API as the classifier's 0/1; -1 if unset.
int ClassOf(v1::Label label);
// The classifier's 0/1 as the API's label.
v1::Label LabelOf(int label);

// RESOURCE_EXHAUSTED when a request carries more than `max` feature vectors.
Status CheckFeatureCount(int count, std::size_t max);

// Feature vectors of a request as the rows of a matrix; none or ragged →
// INVALID_ARGUMENT.
StatusOr<Eigen::MatrixXd> FeatureRows(
    const google::protobuf::RepeatedPtrField<v1::FeatureVector>& rows);

struct LabelledRows {
  Eigen::MatrixXd features;
  std::vector<int> labels;  // -1 where the label is unset
};

// Labelled feature vectors of a request; none or ragged → INVALID_ARGUMENT.
StatusOr<LabelledRows> LabelledRowsOf(
    const google::protobuf::RepeatedPtrField<v1::LabelledFeature>& samples);

// A mapped frame into ComputeMaps' answer: id, supervoxels (with their features if
// `include_features`), target, point labels unless `omit_point_labels`, and the
// timings of the frame's own stages (the caller adds admission, decode and total).
void FillMappedFrame(const session::MappedFrame& mapped, bool include_features,
                     bool omit_point_labels, v1::ComputeMapsResponse* out);

// A session's exported state, without its config (the caller's to fill).
void FillState(const session::SessionState& state, v1::SessionState* out);

// The state of an import: INVALID_ARGUMENT for an RNG state of other than 4 words or
// ragged samples, RESOURCE_EXHAUSTED for more than `max_features` samples.
StatusOr<session::SessionState> StateFromProto(const v1::SessionState& in,
                                               std::size_t max_features);

}  // namespace relmap::service
