// Snapshots in the SQLite store: a model restored from a loaded snapshot predicts
// bit for bit like the original; a damaged blob is DATA_LOSS, never a wrong model.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <cmath>
#include <cstring>
#include <span>
#include <string>

#include "cmm/collaborative_mixture_models.h"
#include "session/snapshot_codec.h"
#include "session/sqlite_session_store.h"
#include "session/store_test_support.h"
#include "support/cmm_training.h"

namespace relmap::session {
namespace {

using testing::MakeRecord;
using testing::Numbered;
using testing::StoreTest;

class SnapshotStoreTest : public StoreTest {
 protected:
  // A model trained on `n` samples of an 8-d XOR problem, with its session.
  cmm::CollaborativeMixtureModels TrainAndCreate(SqliteSessionStore& store, cmm::Variant variant,
                                                 int n) {
    data_ = relmap::testing::Problem(datasets::Problem::kXorBlobs, n, 8, 5);
    SessionRecord record = MakeRecord("s", 8);
    record.cmm_config = cmm::CmmConfig::ForVariant(variant);
    record.cmm_config.seed = 17;
    EXPECT_TRUE(store.CreateSession(record).ok());
    for (int i = 0; i < n; ++i) {
      const Eigen::VectorXd x = data_.features.row(i).transpose();
      EXPECT_TRUE(store
                      .AppendSample("s", Numbered("r", i), std::span<const double>(x.data(), 8),
                                    data_.labels[i])
                      .ok());
    }
    return relmap::testing::Train(data_, record.cmm_config);
  }
  datasets::LabelledSamples data_;
};

class SnapshotStoreRoundTrip : public SnapshotStoreTest,
                               public ::testing::WithParamInterface<cmm::Variant> {};

TEST_P(SnapshotStoreRoundTrip, RestoredModelPredictsBitForBitAfterReopening) {
  auto store = OpenStore();
  auto original = TrainAndCreate(*store, GetParam(), 300);
  ASSERT_GT(original.component_count(0) + original.component_count(1), 2);
  ASSERT_TRUE(store->SaveSnapshot("s", original.Snapshot(), 300).ok());
  store.reset();

  store = OpenStore();
  auto loaded = store->LoadLatestSnapshot("s");
  ASSERT_TRUE(loaded.ok()) << loaded.status().message();
  ASSERT_TRUE(loaded->has_value());
  EXPECT_EQ((*loaded)->sample_count, 300);
  auto restored = cmm::CollaborativeMixtureModels::Restore((*loaded)->snapshot);
  ASSERT_TRUE(restored.ok()) << restored.status().message();

  const Eigen::MatrixXd probe =
      relmap::testing::Problem(datasets::Problem::kXorBlobs, 500, 8, 6).features;
  const Eigen::VectorXd before = original.Predict(probe);
  const Eigen::VectorXd after = restored->Predict(probe);
  EXPECT_EQ(0, std::memcmp(before.data(), after.data(), sizeof(double) * before.size()));
  EXPECT_EQ(original.LogLikelihood(), restored->LogLikelihood());
  // The re-encoded snapshot is byte for byte the stored one: nothing was rounded.
  EXPECT_EQ(*EncodeSnapshot(original.Snapshot()), *EncodeSnapshot(restored->Snapshot()));
}

INSTANTIATE_TEST_SUITE_P(BothVariants, SnapshotStoreRoundTrip,
                         ::testing::Values(cmm::Variant::kCorrected, cmm::Variant::kPaper2018),
                         [](const ::testing::TestParamInfo<cmm::Variant>& test_info) {
                           return std::string(cmm::VariantName(test_info.param));
                         });

TEST_F(SnapshotStoreTest, NoSnapshotYetIsAnEmptyOptional) {
  auto store = OpenStore();
  ASSERT_TRUE(store->CreateSession(MakeRecord("s")).ok());
  auto loaded = store->LoadLatestSnapshot("s");
  ASSERT_TRUE(loaded.ok()) << loaded.status().message();
  EXPECT_FALSE(loaded->has_value());
}

TEST_F(SnapshotStoreTest, SavingReplacesThePreviousSnapshot) {
  auto store = OpenStore();
  auto model = TrainAndCreate(*store, cmm::Variant::kCorrected, 40);
  auto empty = cmm::CollaborativeMixtureModels::Create(model.config(), 8).value();
  ASSERT_TRUE(store->SaveSnapshot("s", empty.Snapshot(), 0).ok());
  ASSERT_TRUE(store->SaveSnapshot("s", model.Snapshot(), 40).ok());
  auto loaded = store->LoadLatestSnapshot("s");
  ASSERT_TRUE(loaded.ok() && loaded->has_value());
  EXPECT_EQ((*loaded)->sample_count, 40);
  EXPECT_EQ((*loaded)->snapshot.labels.size(), 40u);
}

TEST_F(SnapshotStoreTest, SnapshotAheadOfTheStoredSamplesIsRefused) {
  auto store = OpenStore();
  auto model = TrainAndCreate(*store, cmm::Variant::kCorrected, 10);
  EXPECT_EQ(store->SaveSnapshot("s", model.Snapshot(), 11).code(), StatusCode::kFailedPrecondition);
  cmm::CmmSnapshot wrong_dimension = model.Snapshot();
  wrong_dimension.dimension = 4;
  EXPECT_EQ(store->SaveSnapshot("s", wrong_dimension, 10).code(), StatusCode::kInvalidArgument);
}

TEST_F(SnapshotStoreTest, FlippedByteInTheStoredBlobIsDataLoss) {
  {
    auto store = OpenStore();
    auto model = TrainAndCreate(*store, cmm::Variant::kCorrected, 50);
    ASSERT_TRUE(store->SaveSnapshot("s", model.Snapshot(), 50).ok());
  }
  // One bit of byte 101 (inside the features) changes; the length does not.
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path_.c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db,
                         "UPDATE snapshots SET snapshot = CAST(substr(snapshot, 1, 100) ||"
                         " (CASE WHEN substr(snapshot, 101, 1) = x'00' THEN x'01' ELSE x'00' END)"
                         " || substr(snapshot, 102) AS BLOB)",
                         nullptr, nullptr, nullptr),
            SQLITE_OK)
      << sqlite3_errmsg(db);
  sqlite3_close(db);

  auto store = OpenStore();
  const Status status = store->LoadLatestSnapshot("s").status();
  EXPECT_EQ(status.code(), StatusCode::kDataLoss);
  EXPECT_NE(status.message().find("checksum mismatch"), std::string::npos) << status.message();
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

TEST(SnapshotCodec, SnapshotInconsistentWithItsDimensionIsNotEncoded) {
  cmm::CmmSnapshot snapshot;
  snapshot.dimension = 2;
  snapshot.labels = {1};
  snapshot.features = {1.0};
  EXPECT_EQ(EncodeSnapshot(snapshot).status().code(), StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace relmap::session
