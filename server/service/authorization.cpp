// Tokens are compared by their hashes (session/credentials.h): the server keeps no
// token, and the comparison takes the same time whatever the guess.
#include "service/authorization.h"

#include <algorithm>
#include <cctype>

#include "session/credentials.h"

namespace relmap::service {
namespace {

std::optional<std::string> MetadataValue(const grpc::ServerContext& context, std::string_view key) {
  const auto& metadata = context.client_metadata();
  const auto found = metadata.find(grpc::string_ref(key.data(), key.size()));
  if (found == metadata.end()) return std::nullopt;
  return std::string(found->second.data(), found->second.size());
}

}  // namespace

CallCredentials CredentialsOf(const grpc::ServerContext& context) {
  return {MetadataValue(context, "authorization"), MetadataValue(context, "x-relmap-admin-key")};
}

std::optional<std::string_view> BearerToken(std::string_view authorization) {
  constexpr std::string_view kBearer = "bearer ";
  if (authorization.size() <= kBearer.size()) return std::nullopt;
  const bool is_bearer = std::equal(
      kBearer.begin(), kBearer.end(), authorization.begin(),
      [](char want, char got) { return want == std::tolower(static_cast<unsigned char>(got)); });
  if (!is_bearer) return std::nullopt;
  return authorization.substr(kBearer.size());
}

StatusOr<std::shared_ptr<session::Session>> Authorization::SessionFor(const CallCredentials& call,
                                                                      const std::string& id) const {
  if (id.empty()) return InvalidArgumentError("session_id is required");
  const std::optional<std::string_view> token =
      call.authorization ? BearerToken(*call.authorization) : std::nullopt;
  if (!token) {
    return Status(StatusCode::kUnauthenticated,
                  "calls on a session need 'authorization: Bearer <session token>' metadata");
  }
  // Looked up before the token is checked: an unknown session is NOT_FOUND whatever
  // the token.
  auto session = registry_.Find(id);
  if (!session.ok()) return session.status();
  if (!session::TokenMatches(*token, (*session)->token_hash())) {
    return Status(StatusCode::kPermissionDenied, "wrong token for session '" + id + "'");
  }
  return session;
}

Status Authorization::Admin(const CallCredentials& call) const {
  if (admin_key_hash_.empty()) return OkStatus();
  if (!call.admin_key) {
    return Status(StatusCode::kUnauthenticated,
                  "this server needs 'x-relmap-admin-key' metadata to create, list, delete or "
                  "import sessions");
  }
  if (!session::TokenMatches(*call.admin_key, admin_key_hash_)) {
    return Status(StatusCode::kPermissionDenied, "wrong admin key");
  }
  return OkStatus();
}

Status Authorization::Deletion(const CallCredentials& call, const std::string& id) const {
  if (!admin_key_hash_.empty()) return Admin(call);
  return SessionFor(call, id).status();
}

}  // namespace relmap::service
