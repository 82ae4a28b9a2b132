// Flag pairs and numbers by std::from_chars: no locale, no partial reads.
#include "flags.h"

#include <algorithm>
#include <charconv>
#include <cstdlib>

namespace relmap::sim {

bool WantsHelp(int argc, const char* const* argv, int first) {
  for (int i = first; i < argc; ++i) {
    if (std::string_view(argv[i]) == "--help" || std::string_view(argv[i]) == "-h") return true;
  }
  return false;
}

StatusOr<FlagValues> ParseFlagPairs(int argc, const char* const* argv, int first,
                                    std::span<const std::string_view> known) {
  FlagValues flags;
  for (int i = first; i < argc; ++i) {
    const std::string_view word = argv[i];
    if (!word.starts_with("--"))
      return InvalidArgumentError("unexpected argument '" + std::string(word) + "'");
    const std::string_view name = word.substr(2);
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      return InvalidArgumentError("unknown flag " + std::string(word));
    }
    if (i + 1 >= argc) return FlagError(name, "needs a value");
    flags[std::string(name)] = argv[++i];
  }
  return flags;
}

const std::string* FlagValue(const FlagValues& flags, std::string_view name) {
  const auto it = flags.find(name);
  return it == flags.end() ? nullptr : &it->second;
}

Status RequireFlags(const FlagValues& flags, std::initializer_list<std::string_view> names) {
  for (const std::string_view name : names) {
    const std::string* value = FlagValue(flags, name);
    if (value == nullptr || value->empty()) return FlagError(name, "is required");
  }
  return OkStatus();
}

Status ReadServerFlags(const FlagValues& flags, std::string* server, std::string* server_binary) {
  const std::string* address = FlagValue(flags, "server");
  const std::string* binary = FlagValue(flags, "server-binary");
  if (address != nullptr && binary != nullptr) {
    return InvalidArgumentError("--server and --server-binary exclude each other");
  }
  if (address != nullptr) *server = *address;
  if (binary != nullptr) *server_binary = *binary;
  return OkStatus();
}

Status FlagError(std::string_view flag, const std::string& problem) {
  return InvalidArgumentError("--" + std::string(flag) + " " + problem);
}

StatusOr<long long> ParseInteger(std::string_view flag, const std::string& text, long long low,
                                 long long high) {
  long long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) {
    return FlagError(flag, "expects a whole number, got '" + text + "'");
  }
  if (value < low || value > high) {
    return FlagError(flag, "must be in [" + std::to_string(low) + ", " + std::to_string(high) +
                               "], got " + text);
  }
  return value;
}

StatusOr<std::uint64_t> ParseUnsigned(std::string_view flag, const std::string& text) {
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) {
    return FlagError(flag, "expects a whole number >= 0, got '" + text + "'");
  }
  return value;
}

StatusOr<double> ParseUnitInterval(std::string_view flag, const std::string& text) {
  char* end = nullptr;
  const double parsed = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !(parsed >= 0.0 && parsed <= 1.0)) {
    return FlagError(flag, "expects a number in [0, 1], got '" + text + "'");
  }
  return parsed;
}

StatusOr<ImageSize> ParseResolution(const std::string& text) {
  const std::size_t x = text.find('x');
  const Status malformed = FlagError("resolution", "expects WIDTHxHEIGHT, got '" + text + "'");
  if (x == std::string::npos) return malformed;
  StatusOr<long long> width = ParseInteger("resolution", text.substr(0, x), 1, 4096);
  StatusOr<long long> height = ParseInteger("resolution", text.substr(x + 1), 1, 4096);
  if (!width.ok() || !height.ok()) return malformed;
  return ImageSize{static_cast<std::uint32_t>(*width), static_cast<std::uint32_t>(*height)};
}

}  // namespace relmap::sim
