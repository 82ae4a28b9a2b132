// SqliteSessionStore: the store contract on a SQLite file, what only a file can
// get wrong, and the snapshot blob's codec.
#include "session/sqlite_session_store.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "cmm/collaborative_mixture_models.h"
#include "session/snapshot_codec.h"
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

TEST(SnapshotCodec, SnapshotInconsistentWithItsDimensionIsNotEncoded) {
  cmm::CmmSnapshot snapshot;
  snapshot.dimension = 2;
  snapshot.labels = {1};
  snapshot.features = {1.0};
  EXPECT_EQ(EncodeSnapshot(snapshot).status().code(), StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace relmap::session
