// Authorization against its contract: Bearer tokens for a session's calls, the admin
// key for creating, listing, deleting and importing, checked on a call's credentials
// without a gRPC server.
#include "service/authorization.h"

#include <gtest/gtest.h>

#include <string>

#include "session/credentials.h"
#include "session/feature_settings.h"

namespace relmap::service {
namespace {

using session::testing::FeatureSettings;

class AuthorizationTest : public ::testing::Test {
 protected:
  AuthorizationTest() : registry_(4) {
    auto created = registry_.Create(FeatureSettings(), "config", 0);
    EXPECT_TRUE(created.ok());
    id_ = created->session->id();
    token_ = created->token;
  }

  static CallCredentials AuthorizationHeader(const std::string& value) {
    CallCredentials call;
    call.authorization = value;
    return call;
  }
  static CallCredentials Bearer(const std::string& token) {
    return AuthorizationHeader("Bearer " + token);
  }
  static CallCredentials AdminKey(const std::string& key) {
    CallCredentials call;
    call.admin_key = key;
    return call;
  }

  session::SessionRegistry registry_;
  std::string id_;
  std::string token_;
};

TEST(BearerToken, IsTheValueAfterTheSchemeNamedInAnyCase) {
  EXPECT_EQ(BearerToken("Bearer abc"), "abc");
  EXPECT_EQ(BearerToken("bearer abc"), "abc");
  EXPECT_EQ(BearerToken("BEARER abc"), "abc");
}

TEST(BearerToken, IsNoneForAnotherSchemeOrAnEmptyToken) {
  EXPECT_EQ(BearerToken("Basic abc"), std::nullopt);
  EXPECT_EQ(BearerToken("Bearer "), std::nullopt);
  EXPECT_EQ(BearerToken("Bearer"), std::nullopt);
  EXPECT_EQ(BearerToken(""), std::nullopt);
}

TEST_F(AuthorizationTest, TheSessionsOwnTokenGivesTheSession) {
  const Authorization authorization(registry_, "");
  auto session = authorization.SessionFor(Bearer(token_), id_);
  ASSERT_TRUE(session.ok()) << session.status().message();
  EXPECT_EQ((*session)->id(), id_);
}

TEST_F(AuthorizationTest, WithoutABearerTokenACallIsUnauthenticated) {
  const Authorization authorization(registry_, "");
  EXPECT_EQ(authorization.SessionFor({}, id_).status().code(), StatusCode::kUnauthenticated);
  EXPECT_EQ(authorization.SessionFor(AuthorizationHeader("Basic " + token_), id_).status().code(),
            StatusCode::kUnauthenticated);
}

TEST_F(AuthorizationTest, AWrongTokenIsPermissionDenied) {
  const Authorization authorization(registry_, "");
  EXPECT_EQ(authorization.SessionFor(Bearer("guess"), id_).status().code(),
            StatusCode::kPermissionDenied);
}

TEST_F(AuthorizationTest, AnotherSessionsTokenIsPermissionDenied) {
  const Authorization authorization(registry_, "");
  auto other = registry_.Create(FeatureSettings(), "config", 0);
  ASSERT_TRUE(other.ok());
  EXPECT_EQ(authorization.SessionFor(Bearer(other->token), id_).status().code(),
            StatusCode::kPermissionDenied);
}

TEST_F(AuthorizationTest, AnUnknownSessionIsNotFoundWhateverTheToken) {
  const Authorization authorization(registry_, "");
  EXPECT_EQ(authorization.SessionFor(Bearer(token_), "nobody").status().code(),
            StatusCode::kNotFound);
}

TEST_F(AuthorizationTest, AnEmptySessionIdIsInvalidBeforeAnythingElse) {
  const Authorization authorization(registry_, "");
  EXPECT_EQ(authorization.SessionFor({}, "").status().code(), StatusCode::kInvalidArgument);
}

TEST_F(AuthorizationTest, WithoutAnAdminKeyEveryoneIsAdmin) {
  const Authorization authorization(registry_, "");
  EXPECT_TRUE(authorization.Admin({}).ok());
  EXPECT_TRUE(authorization.Admin(AdminKey("anything")).ok());
}

TEST_F(AuthorizationTest, TheAdminKeyIsRequiredAndChecked) {
  const Authorization authorization(registry_, session::Sha256Hex("s3cret"));
  EXPECT_EQ(authorization.Admin({}).code(), StatusCode::kUnauthenticated);
  EXPECT_EQ(authorization.Admin(AdminKey("guess")).code(), StatusCode::kPermissionDenied);
  EXPECT_TRUE(authorization.Admin(AdminKey("s3cret")).ok());
}

TEST_F(AuthorizationTest, WithAnAdminKeyOnlyTheAdministratorDeletes) {
  const Authorization authorization(registry_, session::Sha256Hex("s3cret"));
  EXPECT_EQ(authorization.Deletion(Bearer(token_), id_).code(), StatusCode::kUnauthenticated);
  EXPECT_TRUE(authorization.Deletion(AdminKey("s3cret"), id_).ok());
}

TEST_F(AuthorizationTest, WithoutAnAdminKeyTheSessionsTokenDeletes) {
  const Authorization authorization(registry_, "");
  EXPECT_TRUE(authorization.Deletion(Bearer(token_), id_).ok());
  EXPECT_EQ(authorization.Deletion(Bearer("guess"), id_).code(), StatusCode::kPermissionDenied);
  EXPECT_EQ(authorization.Deletion({}, id_).code(), StatusCode::kUnauthenticated);
}

}  // namespace
}  // namespace relmap::service
