// The seeded random number generator of a session: xoshiro256** (Blackman &
// Vigna, 2018), seeded through splitmix64. Its whole state is four integers, so
// a snapshot restores the exact stream, and its draws do not depend on the
// standard library's distributions (which differ between implementations).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace relmap::cmm {

class Random {
 public:
  using State = std::array<std::uint64_t, 4>;

  explicit Random(std::uint64_t seed = 0);

  static Random FromState(const State& state);
  const State& state() const { return state_; }

  // The next 64 random bits.
  std::uint64_t NextBits();
  // Uniform on [0, 1) with 53 random bits.
  double UniformUnit();
  // Uniform on {0, ..., n-1}, unbiased (Lemire's rejection method). n > 0.
  std::size_t UniformIndex(std::size_t n);

 private:
  State state_{};
};

}  // namespace relmap::cmm
