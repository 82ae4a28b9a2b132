// The `--name value` flags of relmap-sim's commands, and the numbers in them: one
// reading, so that every command words its errors alike.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <map>
#include <span>
#include <string>
#include <string_view>

#include "common/status.h"
#include "image_size.h"

namespace relmap::sim {

// Whether argv[first..argc) asks for the usage (--help or -h anywhere).
bool WantsHelp(int argc, const char* const* argv, int first);

// Flag name (without "--") to its value; the last of repeated flags wins.
using FlagValues = std::map<std::string, std::string, std::less<>>;

// argv[first..argc) as `--name value` pairs, every name one of `known`.
// INVALID_ARGUMENT for a stray word, an unknown flag or a missing value.
StatusOr<FlagValues> ParseFlagPairs(int argc, const char* const* argv, int first,
                                    std::span<const std::string_view> known);

// The value of `name`, or null when it was not given.
const std::string* FlagValue(const FlagValues& flags, std::string_view name);

// INVALID_ARGUMENT "--<name> is required" for the first of `names` missing or empty.
Status RequireFlags(const FlagValues& flags, std::initializer_list<std::string_view> names);

// --server (host:port) and --server-binary into the two strings, left as they are when
// not given; INVALID_ARGUMENT when both are.
Status ReadServerFlags(const FlagValues& flags, std::string* server, std::string* server_binary);

// INVALID_ARGUMENT "--<flag> <problem>".
Status FlagError(std::string_view flag, const std::string& problem);

// A whole number in [low, high].
StatusOr<long long> ParseInteger(std::string_view flag, const std::string& text, long long low,
                                 long long high);
// A whole number >= 0.
StatusOr<std::uint64_t> ParseUnsigned(std::string_view flag, const std::string& text);

// A number in [0, 1].
StatusOr<double> ParseUnitInterval(std::string_view flag, const std::string& text);

// --resolution "640x480": both sides in [1, 4096], the limits of `relmap-sim render`.
StatusOr<ImageSize> ParseResolution(const std::string& text);

}  // namespace relmap::sim
