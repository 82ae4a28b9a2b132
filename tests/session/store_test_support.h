// Shared fixtures of the session store tests: a valid session record, a fresh
// SQLite file per test, and SQL run on that file behind the store's back.
#pragma once

#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "session/store/sqlite/sqlite_session_store.h"

namespace relmap::session::testing {

// "r7" for ("r", 7). Built by append: GCC 12 warns (-Wrestrict, falsely) on
// "r" + std::to_string(i).
inline std::string Numbered(std::string_view prefix, int i) {
  return std::string(prefix).append(std::to_string(i));
}

inline SessionRecord MakeRecord(const std::string& id, int dimension = 3) {
  SessionRecord record;
  record.id = id;
  record.token_hash = "9f86d081884c7d659a2feaa0c55ad015a3bf4f1b2b0b822cd15d6c15b0f00a08";
  record.created_at = Timestamp(std::chrono::microseconds(1'790'000'000'123'456));
  record.config = std::string("\x08\x01\x00\xff opaque", 10);
  record.cmm_config = cmm::CmmConfig::ForVariant(cmm::Variant::kPaper2018);
  record.cmm_config.seed = 0xFEDCBA9876543210u;  // above INT64_MAX: stored as its bit pattern
  record.feature_dimension = dimension;
  return record;
}

// Takes the sessions table back to before summaries (schema version 3), as a server
// of version 2 or older left it; the schema version is for the caller to set.
inline constexpr const char* kSqliteDropSummaryColumns =
    "ALTER TABLE sessions DROP COLUMN samples_non_moveable;"
    "ALTER TABLE sessions DROP COLUMN samples_moveable;"
    "ALTER TABLE sessions DROP COLUMN model_sample_count;"
    "ALTER TABLE sessions DROP COLUMN model_components_non_moveable;"
    "ALTER TABLE sessions DROP COLUMN model_components_moveable;"
    "ALTER TABLE sessions DROP COLUMN last_used_unix_micros;";
inline constexpr const char* kPostgresDropSummaryColumns =
    "ALTER TABLE sessions DROP COLUMN samples_non_moveable, DROP COLUMN samples_moveable,"
    " DROP COLUMN model_sample_count, DROP COLUMN model_components_non_moveable,"
    " DROP COLUMN model_components_moveable, DROP COLUMN last_used_unix_micros;";

// Runs one SQL statement on the SQLite file at `path` behind the store's back, as
// a damaged disk or a future server version would leave it. False (with a test
// failure) if it did not run.
inline bool TamperSqlite(const std::string& path, const char* sql) {
  sqlite3* db = nullptr;
  bool ran = sqlite3_open(path.c_str(), &db) == SQLITE_OK &&
             sqlite3_exec(db, sql, nullptr, nullptr, nullptr) == SQLITE_OK;
  EXPECT_TRUE(ran) << sql << ": " << sqlite3_errmsg(db);
  sqlite3_close(db);
  return ran;
}

// A directory of its own under ::testing::TempDir(), removed afterwards.
class StoreTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    directory_ = std::filesystem::path(::testing::TempDir()) /
                 (std::string("relmap_store_") + info->test_suite_name() + "_" + info->name() +
                  "_" + std::to_string(getpid()));
    std::filesystem::remove_all(directory_);
    std::filesystem::create_directories(directory_);
    path_ = (directory_ / "sessions.db").string();
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  std::unique_ptr<SqliteSessionStore> OpenStore(const SqliteStoreOptions& options = {}) {
    auto store = SqliteSessionStore::Open(path_, options);
    EXPECT_TRUE(store.ok()) << store.status().message();
    return store.ok() ? std::move(store).value() : nullptr;
  }

  std::filesystem::path directory_;
  std::string path_;
};

}  // namespace relmap::session::testing
