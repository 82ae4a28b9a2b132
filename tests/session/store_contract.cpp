// The contract fixture's naming and the SQLite store kind.
#include "session/store_contract.h"

#include <unistd.h>

#include <cctype>
#include <filesystem>

#include "session/store/sqlite/sqlite_session_store.h"
#include "session/store_test_support.h"

namespace relmap::session::testing {

std::string CurrentTestId() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string id = std::string(info->test_suite_name()).append("_").append(info->name());
  for (char& c : id) {
    if (std::isalnum(static_cast<unsigned char>(c)) == 0) c = '_';
  }
  return id;
}

std::string KindName(const ::testing::TestParamInfo<StoreKind>& info) { return info.param.name; }

std::string KindVariantName(
    const ::testing::TestParamInfo<std::tuple<StoreKind, cmm::Variant>>& info) {
  return std::get<0>(info.param).name + "_" +
         std::string(cmm::VariantName(std::get<1>(info.param)));
}

namespace {

class SqliteBackend final : public StoreBackend {
 public:
  explicit SqliteBackend(const std::string& test_id)
      : directory_(std::filesystem::path(::testing::TempDir()) /
                   std::string("relmap_store_")
                       .append(test_id)
                       .append("_")
                       .append(std::to_string(getpid()))) {
    std::filesystem::remove_all(directory_);
    std::filesystem::create_directories(directory_);
  }
  ~SqliteBackend() override { std::filesystem::remove_all(directory_); }

  StatusOr<std::unique_ptr<SessionStore>> Open() override {
    auto store = SqliteSessionStore::Open(path());
    if (!store.ok()) return store.status();
    return std::unique_ptr<SessionStore>(std::move(store).value());
  }
  bool Tamper(const DialectSql& sql) override { return TamperSqlite(path(), sql.sqlite); }

 private:
  std::string path() const { return (directory_ / "sessions.db").string(); }
  std::filesystem::path directory_;
};

}  // namespace

StoreKind SqliteKind() {
  return {"Sqlite", [](const std::string& test_id) -> std::unique_ptr<StoreBackend> {
            return std::make_unique<SqliteBackend>(test_id);
          }};
}

}  // namespace relmap::session::testing
