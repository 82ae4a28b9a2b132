// Every random choice of a replication follows from its seed alone: one stream per
// purpose, one value per iteration, mixed with SplitMix64 (Steele, Lea and Flood, 2014)
// so that neighbouring seeds and iterations give unrelated values.
#pragma once

#include <cstddef>
#include <cstdint>

namespace relmap::sim {

enum class SeedStream : std::uint64_t { kRespawn = 1, kPush = 2, kRandomTarget = 3 };

// SplitMix64's output mix: a bijection of 64-bit words.
inline std::uint64_t MixSeedBits(std::uint64_t x) {
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// The seed of `stream` at `iteration` for the replication seeded `replication_seed`.
inline std::uint64_t IterationSeed(std::uint64_t replication_seed, SeedStream stream,
                                   int iteration) {
  const std::uint64_t base =
      MixSeedBits(replication_seed + 0x9e3779b97f4a7c15ull * static_cast<std::uint64_t>(stream));
  return MixSeedBits(base + static_cast<std::uint64_t>(iteration));
}

// A uniform index in [0, n) from 64 random bits (n > 0), by the top 53 bits as a
// fraction; the bias is below n / 2^53.
inline std::size_t UniformIndex(std::uint64_t bits, std::size_t n) {
  const double unit = static_cast<double>(bits >> 11) * 0x1.0p-53;
  return static_cast<std::size_t>(unit * static_cast<double>(n));
}

}  // namespace relmap::sim
