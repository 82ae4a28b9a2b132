// The relevance server end to end: a real server process on a loopback port,
// talked to through the generated API.
#include <arpa/inet.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <numeric>
#include <thread>
#include <utility>
#include <vector>

#include "integration/server_process.h"
#include "integration/test_support.h"
#include "relmap/v1/relevance_service.grpc.pb.h"

namespace relmap {
namespace {

using testing::PackedTabletop;
using v1::RelevanceService;

class RelevanceServer : public ::testing::Test {
 protected:
  void SetUp() override { stub_ = RelevanceService::NewStub(server_.Channel()); }

  // A session, its id and token.
  std::pair<std::string, std::string> Create(const v1::SessionConfig& config = {}) {
    grpc::ClientContext context;
    v1::CreateSessionRequest request;
    *request.mutable_config() = config;
    v1::CreateSessionResponse response;
    const grpc::Status status = stub_->CreateSession(&context, request, &response);
    EXPECT_TRUE(status.ok()) << status.error_message();
    return {response.session_id(), response.session_token()};
  }

  static void Authorise(grpc::ClientContext& context, const std::string& token) {
    context.AddMetadata("authorization", "Bearer " + token);
  }

  grpc::Status ComputeMaps(const std::string& id, const std::string& token, const v1::Cloud& cloud,
                           v1::ComputeMapsResponse* response, bool include_features = false) {
    grpc::ClientContext context;
    Authorise(context, token);
    v1::ComputeMapsRequest request;
    request.set_session_id(id);
    *request.mutable_cloud() = cloud;
    request.set_include_features(include_features);
    return stub_->ComputeMaps(&context, request, response);
  }

  static v1::PostOutcomeRequest OutcomeRequest(const std::string& id, std::uint64_t frame,
                                               std::uint32_t supervoxel,
                                               const std::string& request_id) {
    v1::PostOutcomeRequest request;
    request.set_session_id(id);
    request.set_frame_id(frame);
    request.set_supervoxel_id(supervoxel);
    request.set_request_id(request_id);
    return request;
  }

  grpc::Status Send(const std::string& token, const v1::PostOutcomeRequest& request,
                    v1::PostOutcomeResponse* response) {
    grpc::ClientContext context;
    Authorise(context, token);
    return stub_->PostOutcome(&context, request, response);
  }

  grpc::Status Post(const std::string& id, const std::string& token, std::uint64_t frame,
                    std::uint32_t supervoxel, v1::Label label, const std::string& request_id,
                    v1::PostOutcomeResponse* response) {
    v1::PostOutcomeRequest request = OutcomeRequest(id, frame, supervoxel, request_id);
    request.set_label(label);
    return Send(token, request, response);
  }

  testing::ServerProcess server_;
  std::unique_ptr<RelevanceService::Stub> stub_;
};

TEST_F(RelevanceServer, MapsOfAFirstCloudAreUntrained) {
  const auto [id, token] = Create();
  v1::ComputeMapsResponse maps;
  const grpc::Status status = ComputeMaps(id, token, PackedTabletop(), &maps);
  ASSERT_TRUE(status.ok()) << status.error_message();
  ASSERT_GT(maps.supervoxels_size(), 10);
  double choice = 0.0;
  for (const v1::Supervoxel& sv : maps.supervoxels()) {
    EXPECT_DOUBLE_EQ(sv.relevance(), 0.5);
    choice += sv.choice();
  }
  EXPECT_NEAR(choice, 1.0, 1e-9);
  EXPECT_LT(maps.target_supervoxel_id(), static_cast<std::uint32_t>(maps.supervoxels_size()));
  EXPECT_EQ(maps.point_labels_size(), 320 * 240);
  EXPECT_GT(maps.timings().total_ms(), 0.0);
}

TEST_F(RelevanceServer, OutcomesAreLearnedOncePerRequestId) {
  const auto [id, token] = Create();
  v1::ComputeMapsResponse maps;
  ASSERT_TRUE(ComputeMaps(id, token, PackedTabletop(), &maps).ok());
  v1::PostOutcomeResponse first;
  ASSERT_TRUE(Post(id, token, maps.frame_id(), maps.target_supervoxel_id(), v1::LABEL_MOVEABLE,
                   "push-1", &first)
                  .ok());
  EXPECT_EQ(first.stats().moveable_samples(), 1u);
  v1::PostOutcomeResponse again;
  ASSERT_TRUE(Post(id, token, maps.frame_id(), maps.target_supervoxel_id(), v1::LABEL_MOVEABLE,
                   "push-1", &again)
                  .ok());
  EXPECT_EQ(again.stats().moveable_samples(), 1u);
  v1::PostOutcomeResponse other;
  ASSERT_TRUE(Post(id, token, maps.frame_id(), 0, v1::LABEL_NOT_MOVEABLE, "push-2", &other).ok());
  EXPECT_EQ(other.stats().non_moveable_samples(), 1u);

  // One sample per class is a unit-covariance component: in 48-d its density
  // (at most (2π)^−24 ≈ 1e−19) leaves every relevance at 0.5. A second moveable
  // sample gives a covariance estimate; the same scene again (same seed, same
  // features) is then relevant where it was pushed.
  v1::PostOutcomeResponse third;
  const std::uint32_t second_moveable = maps.target_supervoxel_id() == 1 ? 2 : 1;
  ASSERT_TRUE(
      Post(id, token, maps.frame_id(), second_moveable, v1::LABEL_MOVEABLE, "push-3", &third).ok());
  EXPECT_EQ(third.stats().moveable_samples(), 2u);
  v1::ComputeMapsResponse next;
  ASSERT_TRUE(ComputeMaps(id, token, PackedTabletop(), &next).ok());
  EXPECT_GT(next.supervoxels(static_cast<int>(maps.target_supervoxel_id())).relevance(), 0.5);
  EXPECT_GT(next.supervoxels(static_cast<int>(second_moveable)).relevance(), 0.5);
}

// moved_supervoxels are learned as moveable and object_supervoxels with the target's label,
// once per request id; bad lists are INVALID_ARGUMENT and learn nothing.
TEST_F(RelevanceServer, OutcomesLabelTheSupervoxelsNamedBesideTheTarget) {
  const auto [id, token] = Create();
  v1::ComputeMapsResponse maps;
  ASSERT_TRUE(ComputeMaps(id, token, PackedTabletop(), &maps).ok());
  ASSERT_GT(maps.supervoxels_size(), 10);
  const auto post = [&](std::uint32_t target, v1::Label label, std::vector<std::uint32_t> moved,
                        std::vector<std::uint32_t> same_object, const std::string& request_id,
                        v1::PostOutcomeResponse* response) {
    v1::PostOutcomeRequest request = OutcomeRequest(id, maps.frame_id(), target, request_id);
    request.set_label(label);
    request.mutable_moved_supervoxels()->Add(moved.begin(), moved.end());
    request.mutable_object_supervoxels()->Add(same_object.begin(), same_object.end());
    return Send(token, request, response);
  };
  v1::PostOutcomeResponse still;
  ASSERT_TRUE(post(0, v1::LABEL_NOT_MOVEABLE, {1}, {2, 3}, "push-1", &still).ok());
  EXPECT_EQ(still.moved_learned(), 1u);
  EXPECT_EQ(still.object_learned(), 2u);
  EXPECT_EQ(still.stats().moveable_samples(), 1u);
  EXPECT_EQ(still.stats().non_moveable_samples(), 3u);
  v1::PostOutcomeResponse again;
  ASSERT_TRUE(post(0, v1::LABEL_NOT_MOVEABLE, {1}, {2, 3}, "push-1", &again).ok());
  EXPECT_EQ(again.stats().non_moveable_samples(), 3u);
  v1::PostOutcomeResponse moved;
  ASSERT_TRUE(post(4, v1::LABEL_MOVEABLE, {}, {5}, "push-2", &moved).ok());
  EXPECT_EQ(moved.stats().moveable_samples(), 3u);
  for (const auto& [moved_ids, object_ids] :
       {std::pair<std::vector<std::uint32_t>, std::vector<std::uint32_t>>{{6}, {6}},
        {{}, {7, 7}},
        {{}, {4}},
        {{}, {static_cast<std::uint32_t>(maps.supervoxels_size())}}}) {
    v1::PostOutcomeResponse rejected;
    EXPECT_EQ(post(4, v1::LABEL_MOVEABLE, moved_ids, object_ids, "bad", &rejected).error_code(),
              grpc::StatusCode::INVALID_ARGUMENT);
  }
  v1::PostOutcomeResponse last;
  ASSERT_TRUE(post(8, v1::LABEL_MOVEABLE, {}, {}, "push-3", &last).ok());
  EXPECT_EQ(last.stats().moveable_samples(), 4u);
  EXPECT_EQ(last.stats().non_moveable_samples(), 3u);
}

TEST_F(RelevanceServer, TheChangeDetectorLabelsFromTheAfterCloud) {
  // Named, not a structured binding: the lambda below captures them, which clang
  // before 16 (clang-tidy's parser here) cannot do with bindings.
  const auto created = Create();
  const std::string& id = created.first;
  const std::string& token = created.second;
  const v1::Cloud before = PackedTabletop(640, 480);
  v1::ComputeMapsResponse maps;
  ASSERT_TRUE(ComputeMaps(id, token, before, &maps).ok());
  // The supervoxel nearest to the camera, and an after cloud in which its points are gone:
  // the camera sees 30 cm further along their rays (what was behind the object).
  std::uint32_t target = 0;
  float nearest = std::numeric_limits<float>::infinity();
  for (const v1::Supervoxel& sv : maps.supervoxels()) {
    if (sv.point_count() >= 50 && sv.centroid().z() < nearest) {
      nearest = sv.centroid().z();
      target = sv.id();
    }
  }
  // Gone: every supervoxel within 8 cm of it, as when an object is taken away
  // (a lone 5 cm patch is within the detector's noise allowance of its border).
  const v1::Vector3& centre = maps.supervoxels(static_cast<int>(target)).centroid();
  std::vector<bool> removed_supervoxel(static_cast<std::size_t>(maps.supervoxels_size()));
  for (const v1::Supervoxel& sv : maps.supervoxels()) {
    const float dx = sv.centroid().x() - centre.x(), dy = sv.centroid().y() - centre.y(),
                dz = sv.centroid().z() - centre.z();
    removed_supervoxel[sv.id()] = dx * dx + dy * dy + dz * dz < 0.08f * 0.08f;
  }
  v1::Cloud after = before;
  std::string points = after.packed().points();
  for (int i = 0; i < maps.point_labels_size(); ++i) {
    const std::int32_t label = maps.point_labels(i);
    if (label >= 0 && removed_supervoxel[static_cast<std::size_t>(label)]) {
      float xyz[3];
      std::memcpy(xyz, &points[static_cast<std::size_t>(i) * 16], sizeof xyz);
      const float farther = (xyz[2] + 0.3f) / xyz[2];
      for (float& v : xyz) v *= farther;
      std::memcpy(&points[static_cast<std::size_t>(i) * 16], xyz, sizeof xyz);
    }
  }
  after.mutable_packed()->set_points(points);

  const auto post = [&](const v1::Cloud& cloud, const std::string& request_id,
                        v1::PostOutcomeResponse* response) {
    v1::PostOutcomeRequest request = OutcomeRequest(id, maps.frame_id(), target, request_id);
    *request.mutable_after_cloud() = cloud;
    return Send(token, request, response);
  };
  v1::PostOutcomeResponse unchanged;
  ASSERT_TRUE(post(before, "same", &unchanged).ok());
  EXPECT_EQ(unchanged.label(), v1::LABEL_NOT_MOVEABLE);
  EXPECT_FALSE(unchanged.evidence().moved());
  EXPECT_EQ(unchanged.stats().non_moveable_samples(), 1u);
  v1::PostOutcomeResponse removed;
  ASSERT_TRUE(post(after, "removed", &removed).ok());
  EXPECT_EQ(removed.label(), v1::LABEL_MOVEABLE);
  EXPECT_TRUE(removed.evidence().moved()) << removed.evidence().ShortDebugString();
  EXPECT_GT(removed.evidence().vacated_points(), 0u);
  // The detector names the other parts it saw go, each one of those taken away, and the
  // session learns them as moveable with the target (learn_moved_object, §4.5).
  for (const std::uint32_t moved : removed.evidence().moved_supervoxels()) {
    EXPECT_TRUE(removed_supervoxel[moved]) << moved;
    EXPECT_NE(moved, target);
  }
  EXPECT_EQ(removed.moved_learned(), removed.evidence().moved_supervoxels_size());
  EXPECT_EQ(removed.stats().moveable_samples(), 1u + removed.moved_learned());
}

TEST_F(RelevanceServer, BadOutcomesGetPreciseStatuses) {
  const auto [id, token] = Create();
  v1::ComputeMapsResponse maps;
  ASSERT_TRUE(ComputeMaps(id, token, PackedTabletop(), &maps).ok());
  v1::PostOutcomeResponse response;
  EXPECT_EQ(
      Post(id, token, maps.frame_id() + 7, 0, v1::LABEL_MOVEABLE, "a", &response).error_code(),
      grpc::StatusCode::FAILED_PRECONDITION);
  EXPECT_EQ(
      Post(id, token, maps.frame_id(), 1000000, v1::LABEL_MOVEABLE, "b", &response).error_code(),
      grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(Post(id, token, maps.frame_id(), 0, v1::LABEL_UNSPECIFIED, "c", &response).error_code(),
            grpc::StatusCode::INVALID_ARGUMENT);
}

TEST_F(RelevanceServer, TokensAreRequiredAndChecked) {
  const auto [id, token] = Create();
  grpc::ClientContext no_token;
  v1::GetSessionRequest request;
  request.set_session_id(id);
  v1::GetSessionResponse response;
  EXPECT_EQ(stub_->GetSession(&no_token, request, &response).error_code(),
            grpc::StatusCode::UNAUTHENTICATED);
  grpc::ClientContext wrong;
  Authorise(wrong, token + "x");
  EXPECT_EQ(stub_->GetSession(&wrong, request, &response).error_code(),
            grpc::StatusCode::PERMISSION_DENIED);
  grpc::ClientContext unknown;
  Authorise(unknown, token);
  request.set_session_id("no-such-session");
  EXPECT_EQ(stub_->GetSession(&unknown, request, &response).error_code(),
            grpc::StatusCode::NOT_FOUND);
  grpc::ClientContext right;
  Authorise(right, token);
  request.set_session_id(id);
  ASSERT_TRUE(stub_->GetSession(&right, request, &response).ok());
  EXPECT_EQ(response.config().classifier().alpha(), 0.25);
  EXPECT_EQ(response.config().feature_dimension(), 48u);
}

TEST_F(RelevanceServer, BadCloudsAreInvalidArguments) {
  const auto [id, token] = Create();
  v1::ComputeMapsResponse maps;
  const std::string header =
      "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";
  v1::Cloud truncated;
  truncated.set_pcd(header + "WIDTH 1000\nHEIGHT 1\nPOINTS 1000\nDATA binary\n");
  EXPECT_EQ(ComputeMaps(id, token, truncated, &maps).error_code(),
            grpc::StatusCode::INVALID_ARGUMENT);
  // A header that claims a billion points is refused as over the server's limit, before
  // any memory is set aside for them.
  v1::Cloud huge;
  huge.set_pcd(header + "WIDTH 1000000000\nHEIGHT 1\nPOINTS 1000000000\nDATA binary\n");
  EXPECT_EQ(ComputeMaps(id, token, huge, &maps).error_code(), grpc::StatusCode::RESOURCE_EXHAUSTED);
  v1::Cloud holes = PackedTabletop();
  std::string points = holes.packed().points();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t i = 0; i < points.size(); i += 16) std::memcpy(&points[i], &nan, 4);
  holes.mutable_packed()->set_points(points);
  EXPECT_EQ(ComputeMaps(id, token, holes, &maps).error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(ComputeMaps(id, token, v1::Cloud{}, &maps).error_code(),
            grpc::StatusCode::INVALID_ARGUMENT);
}

// The crashers the fuzzing of issue 14 found, each now a precise status from a server that
// goes on serving: a packed cloud of (2^32 - 1)^2 points (its size wrapped), and resolutions
// that PCL's octrees abort on or grow without bound with.
TEST_F(RelevanceServer, FuzzedCrashersGetStatusesAndTheServerLives) {
  const auto [id, token] = Create();
  v1::ComputeMapsResponse maps;
  v1::Cloud wrapping;
  wrapping.mutable_packed()->set_width(4294967295u);
  wrapping.mutable_packed()->set_height(4294967295u);
  wrapping.mutable_packed()->set_points(std::string(64, '\0'));
  EXPECT_EQ(ComputeMaps(id, token, wrapping, &maps).error_code(),
            grpc::StatusCode::RESOURCE_EXHAUSTED);

  for (const float resolution : {1e-9f, 1e-30f}) {
    grpc::ClientContext context;
    v1::CreateSessionRequest request;
    request.mutable_config()->mutable_supervoxels()->set_voxel_resolution(resolution);
    v1::CreateSessionResponse response;
    const grpc::Status status = stub_->CreateSession(&context, request, &response);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT) << resolution;
    EXPECT_THAT(status.error_message(), ::testing::HasSubstr("supervoxels.voxel_resolution"));
  }
  {
    grpc::ClientContext context;
    v1::CreateSessionRequest request;
    request.mutable_config()->mutable_change_detector()->set_octree_resolution(1e-9f);
    v1::CreateSessionResponse response;
    const grpc::Status status = stub_->CreateSession(&context, request, &response);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
    EXPECT_THAT(status.error_message(), ::testing::HasSubstr("change.octree_resolution"));
  }
  EXPECT_TRUE(ComputeMaps(id, token, PackedTabletop(), &maps).ok());  // still serving
}

// The features a session learned from a pushed supervoxel, as ExportSession returns them.
std::vector<double> LearnedFeature(RelevanceService::Stub& stub, const std::string& id,
                                   const std::string& token) {
  grpc::ClientContext context;
  context.AddMetadata("authorization", "Bearer " + token);
  v1::ExportSessionRequest request;
  request.set_session_id(id);
  v1::ExportSessionResponse response;
  const grpc::Status status = stub.ExportSession(&context, request, &response);
  EXPECT_TRUE(status.ok()) << status.error_message();
  if (response.state().samples_size() != 1) return {};
  const auto& values = response.state().samples(0).feature().values();
  return {values.begin(), values.end()};
}

// The session's FeatureConfig reaches ComputeMaps: the same supervoxel of the same cloud is
// learned with other colour values (paper2018 conversion) and other FPFH values (raw points)
// than in a default session.
TEST_F(RelevanceServer, FeatureSettingsAreReportedAndChangeTheLearnedFeatures) {
  v1::SessionConfig paper;
  paper.mutable_features()->set_colour(v1::COLOUR_VARIANT_PAPER2018);
  paper.mutable_features()->set_fpfh_scheme(v1::FPFH_SCHEME_RAW_POINTS);
  const auto [paper_id, paper_token] = Create(paper);
  const auto [default_id, default_token] = Create();

  grpc::ClientContext get_context;
  Authorise(get_context, paper_token);
  v1::GetSessionRequest get;
  get.set_session_id(paper_id);
  v1::GetSessionResponse session;
  ASSERT_TRUE(stub_->GetSession(&get_context, get, &session).ok());
  EXPECT_EQ(session.config().features().colour(), v1::COLOUR_VARIANT_PAPER2018);
  EXPECT_EQ(session.config().features().fpfh_scheme(), v1::FPFH_SCHEME_RAW_POINTS);
  EXPECT_FLOAT_EQ(session.config().features().fpfh_radius(), 0.05f);

  std::vector<double> learned[2];
  const std::pair<std::string, std::string> sessions[2] = {{paper_id, paper_token},
                                                           {default_id, default_token}};
  for (int s = 0; s < 2; ++s) {
    v1::ComputeMapsResponse maps;
    ASSERT_TRUE(ComputeMaps(sessions[s].first, sessions[s].second, PackedTabletop(), &maps).ok());
    ASSERT_GT(maps.supervoxels_size(), 0);
    EXPECT_EQ(maps.unusable_supervoxels(), 0u);
    v1::PostOutcomeResponse posted;
    ASSERT_TRUE(Post(sessions[s].first, sessions[s].second, maps.frame_id(), 0, v1::LABEL_MOVEABLE,
                     "push-0", &posted)
                    .ok());
    learned[s] = LearnedFeature(*stub_, sessions[s].first, sessions[s].second);
    ASSERT_EQ(learned[s].size(), 48u);
  }
  // Same segmentation (same supervoxel settings), so supervoxel 0 is the same in both.
  const auto differs = [&](int first, int count) {
    for (int d = first; d < first + count; ++d) {
      if (learned[0][static_cast<std::size_t>(d)] != learned[1][static_cast<std::size_t>(d)]) {
        return true;
      }
    }
    return false;
  };
  EXPECT_TRUE(differs(0, 15)) << "colour histogram";
  EXPECT_TRUE(differs(15, 33)) << "FPFH";
}

// include_features returns, per supervoxel, the very vector PostOutcome learns for it; without
// it a response carries none (48 doubles per supervoxel are more bytes than the rest).
TEST_F(RelevanceServer, MapsIncludeTheLearnedFeaturesOnlyOnRequest) {
  const auto [id, token] = Create();
  v1::ComputeMapsResponse plain;
  ASSERT_TRUE(ComputeMaps(id, token, PackedTabletop(), &plain).ok());
  ASSERT_GT(plain.supervoxels_size(), 1);
  for (const v1::Supervoxel& sv : plain.supervoxels()) EXPECT_EQ(sv.features_size(), 0);

  v1::ComputeMapsResponse maps;
  ASSERT_TRUE(ComputeMaps(id, token, PackedTabletop(), &maps, /*include_features=*/true).ok());
  ASSERT_EQ(maps.supervoxels_size(), plain.supervoxels_size());
  for (const v1::Supervoxel& sv : maps.supervoxels()) {
    ASSERT_EQ(sv.features_size(), 48) << "supervoxel " << sv.id();
    for (const double value : sv.features()) {
      EXPECT_GE(value, 0.0);
      EXPECT_LE(value, 1.0);
    }
  }
  const std::uint32_t pushed = 1;
  v1::PostOutcomeResponse posted;
  ASSERT_TRUE(Post(id, token, maps.frame_id(), pushed, v1::LABEL_MOVEABLE, "push-1", &posted).ok());
  const auto& returned = maps.supervoxels(static_cast<int>(pushed)).features();
  EXPECT_EQ(LearnedFeature(*stub_, id, token),
            std::vector<double>(returned.begin(), returned.end()));
}

TEST_F(RelevanceServer, FeatureSessionsLearnRawVectors) {
  v1::SessionConfig config;
  config.set_feature_dimension(2);
  const auto [id, token] = Create(config);
  grpc::ClientContext add_context;
  Authorise(add_context, token);
  v1::AddSamplesRequest add;
  add.set_session_id(id);
  add.set_request_id("batch-1");
  for (int i = 0; i < 20; ++i) {
    v1::LabelledFeature* sample = add.add_samples();
    sample->mutable_feature()->add_values(i % 2 == 0 ? 0.01 * i : 5 + 0.01 * i);
    sample->mutable_feature()->add_values(0.0);
    sample->set_label(i % 2 == 0 ? v1::LABEL_MOVEABLE : v1::LABEL_NOT_MOVEABLE);
  }
  v1::AddSamplesResponse added;
  ASSERT_TRUE(stub_->AddSamples(&add_context, add, &added).ok());
  EXPECT_EQ(added.stats().moveable_samples(), 10u);

  grpc::ClientContext classify_context;
  Authorise(classify_context, token);
  v1::ClassifyFeaturesRequest classify;
  classify.set_session_id(id);
  for (double x : {0.05, 5.05}) {
    v1::FeatureVector* vector = classify.add_features();
    vector->add_values(x);
    vector->add_values(0.0);
  }
  v1::ClassifyFeaturesResponse relevance;
  ASSERT_TRUE(stub_->ClassifyFeatures(&classify_context, classify, &relevance).ok());
  EXPECT_GT(relevance.relevance(0), 0.5);
  EXPECT_LT(relevance.relevance(1), 0.5);

  grpc::ClientContext ragged_context;
  Authorise(ragged_context, token);
  classify.add_features()->add_values(1.0);
  EXPECT_EQ(stub_->ClassifyFeatures(&ragged_context, classify, &relevance).error_code(),
            grpc::StatusCode::INVALID_ARGUMENT);

  grpc::ClientContext maps_context;
  Authorise(maps_context, token);
  v1::ComputeMapsRequest maps_request;
  maps_request.set_session_id(id);
  *maps_request.mutable_cloud() = PackedTabletop();
  v1::ComputeMapsResponse maps;
  EXPECT_EQ(stub_->ComputeMaps(&maps_context, maps_request, &maps).error_code(),
            grpc::StatusCode::FAILED_PRECONDITION);
}

TEST(RelevanceServerLimits, OversizedMessagesAreResourceExhausted) {
  testing::ServerProcess server({"--max-message-mb", "1"});
  auto stub = RelevanceService::NewStub(server.Channel());
  grpc::ClientContext context;
  v1::CreateSessionRequest create;
  v1::CreateSessionResponse created;
  ASSERT_TRUE(stub->CreateSession(&context, create, &created).ok());
  grpc::ClientContext maps_context;
  maps_context.AddMetadata("authorization", "Bearer " + created.session_token());
  v1::ComputeMapsRequest request;
  request.set_session_id(created.session_id());
  *request.mutable_cloud() = PackedTabletop();  // 320×240×16 B = 1.2 MB
  v1::ComputeMapsResponse response;
  EXPECT_EQ(stub->ComputeMaps(&maps_context, request, &response).error_code(),
            grpc::StatusCode::RESOURCE_EXHAUSTED);
}

TEST(RelevanceServerAdminKey, GuardsCreateListAndDelete) {
  const std::string key_file = ::testing::TempDir() + "/relmap_admin_key";
  std::ofstream(key_file) << "s3cret\n";
  testing::ServerProcess server({"--admin-key-file", key_file});
  auto stub = RelevanceService::NewStub(server.Channel());
  v1::CreateSessionResponse created;
  grpc::ClientContext without;
  EXPECT_EQ(stub->CreateSession(&without, {}, &created).error_code(),
            grpc::StatusCode::UNAUTHENTICATED);
  grpc::ClientContext wrong;
  wrong.AddMetadata("x-relmap-admin-key", "guess");
  EXPECT_EQ(stub->CreateSession(&wrong, {}, &created).error_code(),
            grpc::StatusCode::PERMISSION_DENIED);
  grpc::ClientContext right;
  right.AddMetadata("x-relmap-admin-key", "s3cret");
  ASSERT_TRUE(stub->CreateSession(&right, {}, &created).ok());

  v1::ListSessionsResponse listed;
  grpc::ClientContext list_without;
  EXPECT_EQ(stub->ListSessions(&list_without, {}, &listed).error_code(),
            grpc::StatusCode::UNAUTHENTICATED);
  // The session token alone does not delete when an admin key is set.
  grpc::ClientContext token_only;
  token_only.AddMetadata("authorization", "Bearer " + created.session_token());
  v1::DeleteSessionRequest remove;
  remove.set_session_id(created.session_id());
  v1::DeleteSessionResponse removed;
  EXPECT_EQ(stub->DeleteSession(&token_only, remove, &removed).error_code(),
            grpc::StatusCode::UNAUTHENTICATED);
  grpc::ClientContext admin;
  admin.AddMetadata("x-relmap-admin-key", "s3cret");
  EXPECT_TRUE(stub->DeleteSession(&admin, remove, &removed).ok());
  std::remove(key_file.c_str());
}

TEST(RelevanceServerLimits, BusyWorkerPoolAnswersResourceExhausted) {
  testing::ServerProcess server({"--max-threads", "2"});
  auto stub = RelevanceService::NewStub(server.Channel());
  grpc::ClientContext context;
  v1::CreateSessionResponse created;
  ASSERT_TRUE(stub->CreateSession(&context, {}, &created).ok());
  const v1::Cloud cloud = PackedTabletop(640, 480);  // ~0.25 s of work per call
  std::vector<std::thread> clients;
  std::atomic<int> ok = 0, exhausted = 0, other = 0;
  for (int i = 0; i < 8; ++i) {
    clients.emplace_back([&] {
      grpc::ClientContext call;
      call.AddMetadata("authorization", "Bearer " + created.session_token());
      v1::ComputeMapsRequest request;
      request.set_session_id(created.session_id());
      *request.mutable_cloud() = cloud;
      v1::ComputeMapsResponse response;
      const grpc::Status status = stub->ComputeMaps(&call, request, &response);
      if (status.ok()) {
        ++ok;
      } else if (status.error_code() == grpc::StatusCode::RESOURCE_EXHAUSTED) {
        ++exhausted;
      } else {
        ++other;
      }
    });
  }
  for (std::thread& t : clients) t.join();
  EXPECT_GT(ok.load(), 0);
  EXPECT_GT(exhausted.load(), 0);
  EXPECT_EQ(other.load(), 0);
}

TEST(RelevanceServerTls, ServesTlsWithTheGivenCertificate) {
  const std::string dir = ::testing::TempDir();
  const std::string cert = dir + "/relmap_tls_cert.pem", key = dir + "/relmap_tls_key.pem";
  const std::string make_certificate =
      "openssl req -x509 -newkey rsa:2048 -nodes -days 1 -subj /CN=localhost -addext "
      "subjectAltName=IP:127.0.0.1 -keyout " +
      key + " -out " + cert + " >/dev/null 2>&1";
  if (std::system(make_certificate.c_str()) != 0)
    GTEST_SKIP() << "openssl cannot make a certificate";
  testing::ServerProcess server({"--tls-cert", cert, "--tls-key", key});
  std::ifstream in(cert);
  grpc::SslCredentialsOptions tls;
  tls.pem_root_certs.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  auto secure =
      RelevanceService::NewStub(grpc::CreateChannel(server.address(), grpc::SslCredentials(tls)));
  grpc::ClientContext context;
  v1::CreateSessionResponse created;
  EXPECT_TRUE(secure->CreateSession(&context, {}, &created).ok());
  auto plain = RelevanceService::NewStub(server.Channel());
  grpc::ClientContext plain_context;
  plain_context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(2));
  EXPECT_FALSE(plain->CreateSession(&plain_context, {}, &created).ok());
  std::remove(cert.c_str());
  std::remove(key.c_str());
}

TEST(RelevanceServerMetrics, PrometheusEndpointCountsCallsAndSessions) {
  const std::string port_file = ::testing::TempDir() + "/relmap_metrics_port";
  std::remove(port_file.c_str());
  testing::ServerProcess server(
      {"--metrics-listen", "127.0.0.1:0", "--metrics-port-file", port_file});
  auto stub = RelevanceService::NewStub(server.Channel());
  grpc::ClientContext create_context;
  v1::CreateSessionResponse created;
  ASSERT_TRUE(stub->CreateSession(&create_context, {}, &created).ok());
  grpc::ClientContext get_context;
  v1::GetSessionRequest get;
  get.set_session_id("nope");
  v1::GetSessionResponse response;
  EXPECT_FALSE(stub->GetSession(&get_context, get, &response).ok());

  int port = 0;
  std::ifstream(port_file) >> port;
  ASSERT_GT(port, 0);
  const std::string metrics = testing::HttpGet(port, "/metrics");
  EXPECT_NE(metrics.find("200 OK"), std::string::npos);
  EXPECT_NE(metrics.find("relmap_rpc_total{method=\"CreateSession\",code=\"OK\"} 1"),
            std::string::npos);
  EXPECT_NE(metrics.find("relmap_rpc_total{method=\"GetSession\",code=\"UNAUTHENTICATED\"} 1"),
            std::string::npos);
  EXPECT_NE(metrics.find("relmap_rpc_latency_ms_count{method=\"CreateSession\"} 1"),
            std::string::npos);
  EXPECT_NE(metrics.find("relmap_sessions 1"), std::string::npos);
  EXPECT_NE(testing::HttpGet(port, "/other").find("404"), std::string::npos);
  std::remove(port_file.c_str());
}

TEST(RelevanceServerConfiguration, ConfigFileAndEnvironmentSetLimits) {
  const std::string config = ::testing::TempDir() + "/relmap_server.conf";
  std::ofstream(config) << "# limits for this test\nmax-features-per-request 3\n";
  ::setenv("RELMAP_MAX_SESSIONS", "1", 1);
  testing::ServerProcess server({"--config", config});
  ::unsetenv("RELMAP_MAX_SESSIONS");
  auto stub = RelevanceService::NewStub(server.Channel());

  grpc::ClientContext create_context;
  v1::CreateSessionRequest create;
  create.mutable_config()->set_feature_dimension(1);
  v1::CreateSessionResponse created;
  ASSERT_TRUE(stub->CreateSession(&create_context, create, &created).ok());
  grpc::ClientContext second_context;
  v1::CreateSessionResponse second;
  EXPECT_EQ(stub->CreateSession(&second_context, create, &second).error_code(),
            grpc::StatusCode::RESOURCE_EXHAUSTED);  // RELMAP_MAX_SESSIONS=1

  const auto classify = [&](int vectors) {
    grpc::ClientContext context;
    context.AddMetadata("authorization", "Bearer " + created.session_token());
    v1::ClassifyFeaturesRequest request;
    request.set_session_id(created.session_id());
    for (int i = 0; i < vectors; ++i) request.add_features()->add_values(0.1 * i);
    v1::ClassifyFeaturesResponse response;
    return stub->ClassifyFeatures(&context, request, &response).error_code();
  };
  EXPECT_EQ(classify(3), grpc::StatusCode::OK);
  EXPECT_EQ(classify(4), grpc::StatusCode::RESOURCE_EXHAUSTED);  // the config file's limit
  std::remove(config.c_str());
}

TEST(RelevanceServerLifecycle, SigtermStopsTheServerCleanly) {
  testing::ServerProcess server;
  const int status = server.Stop();
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

}  // namespace
}  // namespace relmap
