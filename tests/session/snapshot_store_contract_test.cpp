// Snapshots in every store kind: a model restored from a loaded snapshot
// predicts bit for bit like the original; a damaged blob is DATA_LOSS, never a
// wrong model.
#include <gtest/gtest.h>

#include <cstring>
#include <span>
#include <string>

#include "cmm/collaborative_mixture_models.h"
#include "session/records/snapshot_codec.h"
#include "session/store_contract.h"
#include "support/cmm_training.h"

namespace relmap::session {
namespace {

using testing::MakeRecord;
using testing::Numbered;
using testing::SessionStoreSnapshotRoundTrip;
using testing::SessionStoreSnapshots;

// A model trained on `n` samples of an 8-d XOR problem, with its session "s" in
// `store` holding the samples.
cmm::CollaborativeMixtureModels TrainAndCreate(SessionStore& store, cmm::Variant variant, int n) {
  const datasets::LabelledSamples data =
      relmap::testing::Problem(datasets::Problem::kXorBlobs, n, 8, 5);
  SessionRecord record = MakeRecord("s", 8);
  record.cmm_config = cmm::CmmConfig::ForVariant(variant);
  record.cmm_config.seed = 17;
  EXPECT_TRUE(store.CreateSession(record).ok());
  for (int i = 0; i < n; ++i) {
    const Eigen::VectorXd x = data.features.row(i).transpose();
    EXPECT_TRUE(store
                    .AppendSample("s", Numbered("r", i), std::span<const double>(x.data(), 8),
                                  data.labels[i])
                    .ok());
  }
  return relmap::testing::Train(data, record.cmm_config);
}

TEST_P(SessionStoreSnapshotRoundTrip, RestoredModelPredictsBitForBitAfterReopening) {
  auto store = OpenStore();
  auto original = TrainAndCreate(*store, variant(), 300);
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

TEST_P(SessionStoreSnapshots, NoSnapshotYetIsAnEmptyOptional) {
  auto store = OpenStore();
  ASSERT_TRUE(store->CreateSession(MakeRecord("s")).ok());
  auto loaded = store->LoadLatestSnapshot("s");
  ASSERT_TRUE(loaded.ok()) << loaded.status().message();
  EXPECT_FALSE(loaded->has_value());
}

TEST_P(SessionStoreSnapshots, SavingReplacesThePreviousSnapshot) {
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

TEST_P(SessionStoreSnapshots, SnapshotAheadOfTheStoredSamplesIsRefused) {
  auto store = OpenStore();
  auto model = TrainAndCreate(*store, cmm::Variant::kCorrected, 10);
  EXPECT_EQ(store->SaveSnapshot("s", model.Snapshot(), 11).code(), StatusCode::kFailedPrecondition);
  cmm::CmmSnapshot wrong_dimension = model.Snapshot();
  wrong_dimension.dimension = 4;
  EXPECT_EQ(store->SaveSnapshot("s", wrong_dimension, 10).code(), StatusCode::kInvalidArgument);
}

TEST_P(SessionStoreSnapshots, FlippedByteInTheStoredBlobIsDataLoss) {
  {
    auto store = OpenStore();
    auto model = TrainAndCreate(*store, cmm::Variant::kCorrected, 50);
    ASSERT_TRUE(store->SaveSnapshot("s", model.Snapshot(), 50).ok());
  }
  // One bit of byte 101 (inside the features) changes; the length does not.
  ASSERT_TRUE(Tamper(
      {"UPDATE snapshots SET snapshot = CAST(substr(snapshot, 1, 100) ||"
       " (CASE WHEN substr(snapshot, 101, 1) = x'00' THEN x'01' ELSE x'00' END)"
       " || substr(snapshot, 102) AS BLOB)",
       "UPDATE snapshots SET snapshot = set_byte(snapshot, 100, get_byte(snapshot, 100) # 1)"}));

  auto store = OpenStore();
  const Status status = store->LoadLatestSnapshot("s").status();
  EXPECT_EQ(status.code(), StatusCode::kDataLoss);
  EXPECT_NE(status.message().find("checksum mismatch"), std::string::npos) << status.message();
}

}  // namespace
}  // namespace relmap::session
