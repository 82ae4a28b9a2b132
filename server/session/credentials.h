// Session ids and tokens: random, and tokens kept only as SHA-256 hashes.
#pragma once

#include <string>
#include <string_view>

namespace relmap::session {

// `bytes` random bytes from the operating system (getrandom), as lower-case hex.
std::string RandomHex(int bytes);

// SHA-256 of `text` as lower-case hex.
std::string Sha256Hex(std::string_view text);

// Whether `token` hashes to `token_hash`, compared in constant time.
bool TokenMatches(std::string_view token, std::string_view token_hash);

}  // namespace relmap::session
