// One throw-away PostgreSQL per test program, a schema per test.
#include "session/postgres_backend.h"

#include <gtest/gtest.h>

#include <atomic>
#include <memory>

namespace relmap::session::testing {
namespace {

using relmap::testing::PostgresInstance;

constexpr char kDatabase[] = "relmap";

std::unique_ptr<PostgresInstance>& Instance() {
  static std::unique_ptr<PostgresInstance> instance;
  return instance;
}

class PostgresEnvironment final : public ::testing::Environment {
 public:
  void SetUp() override {
    auto started = PostgresInstance::Start();
    ASSERT_TRUE(started.ok()) << started.status().message();
    const Status created = (*started)->CreateDatabase(kDatabase);
    ASSERT_TRUE(created.ok()) << created.message();
    Instance() = std::move(started).value();
  }
  void TearDown() override { Instance().reset(); }
};

[[maybe_unused]] const auto* const kEnvironment =
    ::testing::AddGlobalTestEnvironment(new PostgresEnvironment);

class PostgresBackend final : public StoreBackend {
 public:
  explicit PostgresBackend(PostgresScratch scratch) : scratch_(std::move(scratch)) {}

  StatusOr<std::unique_ptr<SessionStore>> Open() override {
    auto store = PostgresSessionStore::Open(scratch_.uri);
    if (!store.ok()) return store.status();
    return std::unique_ptr<SessionStore>(std::move(store).value());
  }
  bool Tamper(const DialectSql& sql) override {
    const Status status = SharedPostgres()->Execute(
        scratch_.database, "SET search_path TO " + scratch_.schema + "; " + sql.postgres);
    EXPECT_TRUE(status.ok()) << status.message();
    return status.ok();
  }

 private:
  PostgresScratch scratch_;
};

}  // namespace

PostgresInstance* SharedPostgres() { return Instance().get(); }

std::optional<PostgresScratch> NewPostgresScratch() {
  static std::atomic<int> next{0};
  PostgresInstance* instance = SharedPostgres();
  if (instance == nullptr) {
    ADD_FAILURE() << "the test PostgreSQL server did not start";
    return std::nullopt;
  }
  PostgresScratch scratch;
  scratch.database = kDatabase;
  scratch.schema = std::string("t").append(std::to_string(next++));
  const Status created = instance->Execute(kDatabase, "CREATE SCHEMA " + scratch.schema);
  if (!created.ok()) {
    ADD_FAILURE() << created.message();
    return std::nullopt;
  }
  // options=-c search_path=<schema>, percent-encoded in the URI's query.
  scratch.uri = instance->Uri(kDatabase) + "?options=-c%20search_path%3D" + scratch.schema;
  return scratch;
}

StoreKind PostgresKind() {
  return {"Postgres", [](const std::string&) -> std::unique_ptr<StoreBackend> {
            auto scratch = NewPostgresScratch();
            if (!scratch.has_value()) return nullptr;
            return std::make_unique<PostgresBackend>(std::move(scratch).value());
          }};
}

}  // namespace relmap::session::testing
