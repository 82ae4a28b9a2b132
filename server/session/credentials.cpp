// Random ids from std::random_device (getrandom on Linux), hashes from OpenSSL.
#include "session/credentials.h"

#include <openssl/crypto.h>
#include <openssl/evp.h>

#include <array>
#include <random>

namespace relmap::session {
namespace {

std::string Hex(const unsigned char* data, std::size_t size) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string out;
  out.reserve(2 * size);
  for (std::size_t i = 0; i < size; ++i) {
    out.push_back(kDigits[data[i] >> 4]);
    out.push_back(kDigits[data[i] & 15]);
  }
  return out;
}

}  // namespace

std::string RandomHex(int bytes) {
  std::random_device device;
  std::string out;
  std::vector<unsigned char> buffer(static_cast<std::size_t>(bytes));
  for (auto& b : buffer) b = static_cast<unsigned char>(device() & 0xff);
  return Hex(buffer.data(), buffer.size());
}

std::string Sha256Hex(std::string_view text) {
  std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
  unsigned int size = 0;
  EVP_Digest(text.data(), text.size(), digest.data(), &size, EVP_sha256(), nullptr);
  return Hex(digest.data(), size);
}

bool TokenMatches(std::string_view token, std::string_view token_hash) {
  const std::string hash = Sha256Hex(token);
  return hash.size() == token_hash.size() &&
         CRYPTO_memcmp(hash.data(), token_hash.data(), hash.size()) == 0;
}

}  // namespace relmap::session
