// The fixture of the store contract tests, which every SessionStore
// implementation passes: each test program instantiates the suites with its
// store kinds (RELMAP_INSTANTIATE_STORE_CONTRACT).
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <tuple>

#include "cmm/config.h"
#include "session/store_backend.h"
#include "session/store_test_support.h"

namespace relmap::session::testing {

// "SuiteName_TestName/Kind", without the characters a database name dislikes.
std::string CurrentTestId();

template <typename Param>
class StoreContractBase : public ::testing::TestWithParam<Param> {
 protected:
  virtual const StoreKind& Kind() const = 0;
  void SetUp() override {
    backend_ = Kind().make(CurrentTestId());
    ASSERT_NE(backend_, nullptr) << "no " << Kind().name << " database for this test";
  }
  void TearDown() override { backend_.reset(); }

  // A new store instance; nullptr (with a test failure) if it does not open.
  std::unique_ptr<SessionStore> OpenStore() {
    auto store = backend_->Open();
    EXPECT_TRUE(store.ok()) << store.status().message();
    return store.ok() ? std::move(store).value() : nullptr;
  }
  StatusOr<std::unique_ptr<SessionStore>> TryOpenStore() { return backend_->Open(); }
  bool Tamper(const DialectSql& sql) { return backend_->Tamper(sql); }

  std::unique_ptr<StoreBackend> backend_;
};

class StoreContract : public StoreContractBase<StoreKind> {
 protected:
  const StoreKind& Kind() const override { return GetParam(); }
};

// Per store kind and CMM variant.
class StoreVariantContract : public StoreContractBase<std::tuple<StoreKind, cmm::Variant>> {
 protected:
  const StoreKind& Kind() const override { return std::get<0>(GetParam()); }
  cmm::Variant variant() const { return std::get<1>(GetParam()); }
};

// The suites of the contract, each a StoreContract (or StoreVariantContract).
class SessionStoreSessions : public StoreContract {};
class SessionStoreSamples : public StoreContract {};
class SessionStoreSnapshots : public StoreContract {};
class SessionStoreSnapshotRoundTrip : public StoreVariantContract {};
class SessionStoreDurability : public StoreContract {};

std::string KindName(const ::testing::TestParamInfo<StoreKind>& info);
std::string KindVariantName(
    const ::testing::TestParamInfo<std::tuple<StoreKind, cmm::Variant>>& info);

}  // namespace relmap::session::testing

// Runs every contract suite against the store kind `kind` (a StoreKind).
#define RELMAP_INSTANTIATE_STORE_CONTRACT(prefix, kind)                             \
  INSTANTIATE_TEST_SUITE_P(prefix, SessionStoreSessions, ::testing::Values(kind),   \
                           ::relmap::session::testing::KindName);                   \
  INSTANTIATE_TEST_SUITE_P(prefix, SessionStoreSamples, ::testing::Values(kind),    \
                           ::relmap::session::testing::KindName);                   \
  INSTANTIATE_TEST_SUITE_P(prefix, SessionStoreSnapshots, ::testing::Values(kind),  \
                           ::relmap::session::testing::KindName);                   \
  INSTANTIATE_TEST_SUITE_P(                                                         \
      prefix, SessionStoreSnapshotRoundTrip,                                        \
      ::testing::Combine(::testing::Values(kind),                                   \
                         ::testing::Values(::relmap::cmm::Variant::kCorrected,      \
                                           ::relmap::cmm::Variant::kPaper2018)),    \
      ::relmap::session::testing::KindVariantName);                                 \
  INSTANTIATE_TEST_SUITE_P(prefix, SessionStoreDurability, ::testing::Values(kind), \
                           ::relmap::session::testing::KindName)
