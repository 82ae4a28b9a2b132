// Every random choice of a replication follows from its seed alone: one stream per
// purpose, one value per iteration, mixed with SplitMix64 (Steele, Lea and Flood, 2014)
// so that neighbouring seeds and iterations give unrelated values.
#pragma once

#include <cstddef>
#include <cstdint>

#include "common/random.h"

namespace relmap::sim {

enum class SeedStream : std::uint64_t { kRespawn = 1, kPush = 2, kRandomTarget = 3 };

// The seed of `stream` at `iteration` for the replication seeded `replication_seed`.
inline std::uint64_t IterationSeed(std::uint64_t replication_seed, SeedStream stream,
                                   int iteration) {
  const std::uint64_t base =
      SplitMix64Mix(replication_seed + kSplitMix64Gamma * static_cast<std::uint64_t>(stream));
  return SplitMix64Mix(base + static_cast<std::uint64_t>(iteration));
}

// A uniform index in [0, n) from 64 random bits (n > 0), by the top 53 bits as a
// fraction; the bias is below n / 2^53.
inline std::size_t UniformIndex(std::uint64_t bits, std::size_t n) {
  return static_cast<std::size_t>(UnitFromBits(bits) * static_cast<double>(n));
}

}  // namespace relmap::sim
