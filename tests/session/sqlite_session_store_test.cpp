// SqliteSessionStore: the store contract on a SQLite file, what only a file can
// get wrong, and the snapshot blob's codec.
#include "session/store/sqlite/sqlite_session_store.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <fstream>
#include <string>

#include "cmm/collaborative_mixture_models.h"
#include "session/records/snapshot_codec.h"
#include "session/store_contract.h"

namespace relmap::session {
namespace {

using testing::SessionStoreDurability;
using testing::SessionStoreSamples;
using testing::SessionStoreSessions;
using testing::SessionStoreSnapshotRoundTrip;
using testing::SessionStoreSnapshots;
using testing::StoreTest;

RELMAP_INSTANTIATE_STORE_CONTRACT(Contract, testing::SqliteKind());

using SqliteSessionStoreFile = StoreTest;

TEST_F(SqliteSessionStoreFile, FileThatIsNotADatabaseIsDataLoss) {
  std::ofstream(path_) << std::string(4096, 'x');
  auto store = SqliteSessionStore::Open(path_);
  ASSERT_FALSE(store.ok());
  EXPECT_EQ(store.status().code(), StatusCode::kDataLoss);
  EXPECT_NE(store.status().message().find("not a database"), std::string::npos)
      << store.status().message();
}

TEST_F(SqliteSessionStoreFile, MissingDirectoryIsUnavailable) {
  auto store = SqliteSessionStore::Open((directory_ / "no" / "such" / "dir.db").string());
  ASSERT_FALSE(store.ok());
  EXPECT_EQ(store.status().code(), StatusCode::kUnavailable);
  EXPECT_NE(store.status().message().find("unable to open"), std::string::npos)
      << store.status().message();
}

TEST_F(SqliteSessionStoreFile, AnExclusiveStoreKeepsOtherExclusiveOpensOutUntilItCloses) {
  const SqliteStoreOptions exclusive{.exclusive = true};
  auto first = SqliteSessionStore::Open(path_, exclusive);
  ASSERT_TRUE(first.ok()) << first.status().message();
  auto second = SqliteSessionStore::Open(path_, exclusive);
  ASSERT_FALSE(second.ok());
  EXPECT_EQ(second.status().code(), StatusCode::kFailedPrecondition);
  EXPECT_NE(second.status().message().find("in use by another server"), std::string::npos)
      << second.status().message();
  // Tools and tests that only read or repair the file are not exclusive.
  EXPECT_TRUE(SqliteSessionStore::Open(path_).ok());
  first->reset();
  EXPECT_TRUE(SqliteSessionStore::Open(path_, exclusive).ok());
}

TEST(SnapshotCodec, EveryTruncationIsDataLoss) {
  auto model = cmm::CollaborativeMixtureModels::Create(cmm::CmmConfig{}, 2).value();
  ASSERT_TRUE(model.Add(Eigen::Vector2d(0, 0), 1).ok());
  ASSERT_TRUE(model.Add(Eigen::Vector2d(3, 1), 0).ok());
  const std::string blob = *EncodeSnapshot(model.Snapshot());
  for (std::size_t size = 0; size < blob.size(); ++size) {
    EXPECT_EQ(DecodeSnapshot(std::string_view(blob).substr(0, size)).status().code(),
              StatusCode::kDataLoss)
        << "truncated to " << size << " bytes";
  }
  EXPECT_TRUE(DecodeSnapshot(blob).ok());
}

TEST(SnapshotCodec, ScatterThatIsNotSymmetricBitForBitRoundTripsInFull) {
  cmm::CmmSnapshot snapshot;
  snapshot.dimension = 2;
  snapshot.features = {1.0, 2.0};
  snapshot.labels = {1};
  // Column-major [[1, -0.0], [0.0, 2]]: equal as numbers, not as bits.
  snapshot.components[1].push_back({{0}, {1.0, 2.0}, {1.0, 0.0, -0.0, 2.0}, 1.0});
  snapshot.components[0].push_back({{0}, {1.0, 2.0}, {1.0, 0.5, 0.5, 2.0}, 1.0});
  auto decoded = DecodeSnapshot(*EncodeSnapshot(snapshot));
  ASSERT_TRUE(decoded.ok()) << decoded.status().message();
  EXPECT_TRUE(std::signbit(decoded->components[1][0].scatter[2]));
  EXPECT_FALSE(std::signbit(decoded->components[1][0].scatter[1]));
  EXPECT_EQ(decoded->components[0][0].scatter, snapshot.components[0][0].scatter);
}

TEST(SnapshotCodec, CorrectedRoundTripsItsOptionsPriorAndCalibration) {
  cmm::CmmConfig config = cmm::CmmConfig::ForVariant(cmm::Variant::kCorrected);
  config.variance_floor = 0.05;
  config.fit_label_noise = true;
  auto model = cmm::CollaborativeMixtureModels::Create(config, 2).value();
  for (int i = 0; i < 12; ++i) {
    ASSERT_TRUE(model.Add(Eigen::Vector2d(0.1 * i, i % 3), i % 2).ok());
  }
  const cmm::CmmSnapshot snapshot = model.Snapshot();
  auto decoded = DecodeSnapshot(*EncodeSnapshot(snapshot));
  ASSERT_TRUE(decoded.ok()) << decoded.status().message();
  EXPECT_EQ(decoded->config.variant, cmm::Variant::kCorrected);
  EXPECT_EQ(decoded->config.covariance, cmm::CovarianceEstimate::kPooledPrior);
  EXPECT_EQ(decoded->config.acceptance, cmm::AcceptanceTest::kLeaveOneOut);
  EXPECT_EQ(decoded->config.split_overlap, cmm::SplitOverlap::kOtherSamples);
  EXPECT_EQ(decoded->config.prediction, cmm::Prediction::kCalibrated);
  EXPECT_EQ(decoded->config.variance_floor, 0.05);
  EXPECT_TRUE(decoded->config.fit_label_noise);
  EXPECT_EQ(decoded->prior_pseudo_samples, snapshot.prior_pseudo_samples);
  EXPECT_EQ(decoded->temperature, snapshot.temperature);
  EXPECT_EQ(decoded->label_noise, snapshot.label_noise);
  EXPECT_GT(decoded->prior_pseudo_samples, 0.0);
}

// The version 1 blob of a snapshot: the version word 1, none of version 2's
// config options (25 bytes after the switch bits) and state (24 bytes before
// the checksum), and the checksum recomputed. Variant code 0 meant corrected.
std::string VersionOneBlob(std::string blob) {
  constexpr std::size_t kConfigStart = 4 + 4;                // magic, version
  constexpr std::size_t kSwitchBitsEnd = kConfigStart + 26;  // u8 + 2 f64 + u64 + u8
  blob.replace(4, 4, std::string("\x01\x00\x00\x00", 4));
  blob.erase(kSwitchBitsEnd, 25);
  blob.erase(blob.size() - 4 - 24, 24);
  blob.resize(blob.size() - 4);
  uLong crc = crc32(0L, Z_NULL, 0);
  crc = crc32(crc, reinterpret_cast<const Bytef*>(blob.data()), static_cast<uInt>(blob.size()));
  for (int i = 0; i < 4; ++i) blob.push_back(static_cast<char>((crc >> (8 * i)) & 0xff));
  return blob;
}

TEST(SnapshotCodec, AVersionOneSnapshotLoadsAsCorrectedV1AndPredictsAsBefore) {
  auto model = cmm::CollaborativeMixtureModels::Create(
                   cmm::CmmConfig::ForVariant(cmm::Variant::kCorrectedV1), 2)
                   .value();
  for (int i = 0; i < 12; ++i) {
    ASSERT_TRUE(model.Add(Eigen::Vector2d(0.1 * i, i % 3), i % 2).ok());
  }
  const std::string v1 = VersionOneBlob(*EncodeSnapshot(model.Snapshot()));
  auto decoded = DecodeSnapshot(v1);
  ASSERT_TRUE(decoded.ok()) << decoded.status().message();
  EXPECT_EQ(decoded->config.variant, cmm::Variant::kCorrectedV1);
  EXPECT_EQ(decoded->config.covariance, cmm::CovarianceEstimate::kRidge);
  EXPECT_EQ(decoded->config.acceptance, cmm::AcceptanceTest::kTrainingLikelihood);
  auto restored = cmm::CollaborativeMixtureModels::Restore(*decoded);
  ASSERT_TRUE(restored.ok()) << restored.status().message();
  const Eigen::MatrixXd points = Eigen::MatrixXd::Random(20, 2);
  EXPECT_TRUE((restored->Predict(points).array() == model.Predict(points).array()).all());
  // Version 1 knew no variant 2.
  std::string unknown = v1;
  unknown[8] = 2;
  EXPECT_EQ(DecodeSnapshot(unknown).status().code(), StatusCode::kDataLoss);
}

TEST_F(SqliteSessionStoreFile, SessionsStoredAsCorrectedBeforeVersionTwoLoadAsCorrectedV1) {
  {
    auto store = SqliteSessionStore::Open(path_);
    ASSERT_TRUE(store.ok()) << store.status().message();
    SessionRecord record = testing::MakeRecord("old");
    record.cmm_config = cmm::CmmConfig::ForVariant(cmm::Variant::kCorrected);
    ASSERT_TRUE((*store)->CreateSession(record).ok());
    ASSERT_TRUE((*store)->CreateSession(testing::MakeRecord("paper")).ok());
  }
  // What a schema-1 server left: "corrected" meant today's corrected_v1.
  ASSERT_TRUE(testing::TamperSqlite(path_, testing::kSqliteDropSummaryColumns));
  ASSERT_TRUE(testing::TamperSqlite(path_, "UPDATE schema_version SET version = 1"));
  ASSERT_TRUE(testing::TamperSqlite(
      path_, "UPDATE sessions SET cmm_variant = 'corrected' WHERE id = 'old'"));
  auto store = SqliteSessionStore::Open(path_);
  ASSERT_TRUE(store.ok()) << store.status().message();
  auto old = (*store)->LoadSession("old");
  ASSERT_TRUE(old.ok()) << old.status().message();
  EXPECT_EQ(old->cmm_config.variant, cmm::Variant::kCorrectedV1);
  EXPECT_EQ(old->cmm_config.covariance, cmm::CovarianceEstimate::kRidge);
  EXPECT_EQ((*store)->LoadSession("paper")->cmm_config.variant, cmm::Variant::kPaper2018);
  // A session created under today's schema keeps today's corrected.
  SessionRecord fresh = testing::MakeRecord("new");
  fresh.cmm_config = cmm::CmmConfig::ForVariant(cmm::Variant::kCorrected);
  ASSERT_TRUE((*store)->CreateSession(fresh).ok());
  EXPECT_EQ((*store)->LoadSession("new")->cmm_config.variant, cmm::Variant::kCorrected);
  EXPECT_EQ((*store)->LoadSession("new")->cmm_config.covariance,
            cmm::CovarianceEstimate::kPooledPrior);
}

TEST(SnapshotCodec, SnapshotInconsistentWithItsDimensionIsNotEncoded) {
  cmm::CmmSnapshot snapshot;
  snapshot.dimension = 2;
  snapshot.labels = {1};
  snapshot.features = {1.0};
  EXPECT_EQ(EncodeSnapshot(snapshot).status().code(), StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace relmap::session
