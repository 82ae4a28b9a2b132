// relmap's seeded random numbers, for the server and every program: SplitMix64
// (Steele, Lea and Flood, 2014) to derive seeds and indexed values, and xoshiro256**
// (Blackman & Vigna, 2018) as the generator. The generator's whole state is four
// integers, so a snapshot restores the exact stream, and no draw depends on the
// standard library's distributions (which differ between implementations).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace relmap {

// SplitMix64's increment, the golden ratio in 64 bits.
inline constexpr std::uint64_t kSplitMix64Gamma = 0x9e3779b97f4a7c15ULL;

// SplitMix64's output function: a bijection of 64-bit words whose outputs on
// consecutive inputs pass BigCrush, so neighbouring seeds give unrelated values.
constexpr std::uint64_t SplitMix64Mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// The output of a SplitMix64 stream whose state is `state` before the step.
constexpr std::uint64_t SplitMix64At(std::uint64_t state) {
  return SplitMix64Mix(state + kSplitMix64Gamma);
}

// One step of a SplitMix64 stream: advances `state` and returns its output.
constexpr std::uint64_t SplitMix64Next(std::uint64_t& state) {
  state += kSplitMix64Gamma;
  return SplitMix64Mix(state);
}

// Uniform on [0, 1) from the top 53 of 64 random bits: exactly representable, never 1.
constexpr double UnitFromBits(std::uint64_t bits) {
  return static_cast<double>(bits >> 11) * 0x1.0p-53;
}

// xoshiro256**, seeded through SplitMix64.
class Random {
 public:
  using State = std::array<std::uint64_t, 4>;

  explicit Random(std::uint64_t seed = 0);

  static Random FromState(const State& state);
  const State& state() const { return state_; }

  // The next 64 random bits.
  std::uint64_t NextBits();
  // Uniform on [0, 1) with 53 random bits.
  double UniformUnit() { return UnitFromBits(NextBits()); }
  // Uniform on {0, ..., n-1}, unbiased (Lemire's rejection method). n > 0.
  std::size_t UniformIndex(std::size_t n);

 private:
  State state_{};
};

}  // namespace relmap
