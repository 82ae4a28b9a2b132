// Who may call what. A session's calls need its token as a Bearer token; the admin
// key, when the server has one, guards creating, listing, deleting and importing
// sessions. The checks read a call's credentials, not its gRPC context, so that
// they can be tested without a server.
#pragma once

#include <grpcpp/server_context.h>

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "common/status.h"
#include "session/registry/session_registry.h"
#include "session/session.h"

namespace relmap::service {

// The credentials a call presents: its metadata's values, if it carries them.
struct CallCredentials {
  std::optional<std::string> authorization;  // "authorization"
  std::optional<std::string> admin_key;      // "x-relmap-admin-key"
};

CallCredentials CredentialsOf(const grpc::ServerContext& context);

// The token of an "authorization" value of the Bearer scheme (its name in any case,
// RFC 7235 §2.1); nullopt for another scheme or an empty token.
std::optional<std::string_view> BearerToken(std::string_view authorization);

class Authorization {
 public:
  // `admin_key_hash`: SHA-256 hex of the admin key, or empty for none.
  Authorization(session::SessionRegistry& registry, std::string admin_key_hash)
      : registry_(registry), admin_key_hash_(std::move(admin_key_hash)) {}

  // The session `id`, if the call's Bearer token is its token: INVALID_ARGUMENT for
  // an empty id, UNAUTHENTICATED without a Bearer token, PERMISSION_DENIED with a
  // wrong one; the registry's status for a session it cannot give (NOT_FOUND, or
  // UNAVAILABLE while another server owns it).
  StatusOr<std::shared_ptr<session::Session>> SessionFor(const CallCredentials& call,
                                                         const std::string& id) const;

  // OK when the server has no admin key or the call's matches; UNAUTHENTICATED
  // without one, PERMISSION_DENIED with a wrong one.
  Status Admin(const CallCredentials& call) const;

  // With an admin key the administrator deletes any session; without one, a
  // session's own token is needed.
  Status Deletion(const CallCredentials& call, const std::string& id) const;

 private:
  session::SessionRegistry& registry_;
  const std::string admin_key_hash_;
};

}  // namespace relmap::service
