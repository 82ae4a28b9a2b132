// The random numbers of relmap-load: SplitMix64 (Steele, Lea and Flood, 2014), so
// that every seed, label coin and backoff jitter follows from --seed alone.
#pragma once

#include <cstdint>

namespace relmap::load {

// One SplitMix64 output step: a bijective mix of `x` whose outputs pass BigCrush.
inline std::uint64_t Mix64(std::uint64_t x) {
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// A SplitMix64 stream: the state advances by the golden-ratio increment.
class SeededRandom {
 public:
  explicit SeededRandom(std::uint64_t seed) : state_(seed) {}

  std::uint64_t Next() { return Mix64(state_ += 0x9e3779b97f4a7c15ull); }
  // Uniform in [0, 1): the top 53 bits as a double's mantissa.
  double NextUnit() { return static_cast<double>(Next() >> 11) * 0x1.0p-53; }

 private:
  std::uint64_t state_;
};

}  // namespace relmap::load
