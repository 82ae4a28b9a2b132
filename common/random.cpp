// xoshiro256** and splitmix64, after the public-domain reference code by
// David Blackman and Sebastiano Vigna (https://prng.di.unimi.it/).
#include "common/random.h"

#include <cassert>

namespace relmap {
namespace {

__extension__ using Uint128 = unsigned __int128;

std::uint64_t RotateLeft(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

}  // namespace

Random::Random(std::uint64_t seed) {
  // splitmix64 spreads any seed, 0 included, over a state that is never all zero.
  for (auto& word : state_) word = SplitMix64Next(seed);
}

Random Random::FromState(const State& state) {
  Random random;
  random.state_ = state;
  return random;
}

std::uint64_t Random::NextBits() {
  const std::uint64_t result = RotateLeft(state_[1] * 5, 7) * 9;
  const std::uint64_t t = state_[1] << 17;
  state_[2] ^= state_[0];
  state_[3] ^= state_[1];
  state_[1] ^= state_[2];
  state_[0] ^= state_[3];
  state_[2] ^= t;
  state_[3] = RotateLeft(state_[3], 45);
  return result;
}

std::size_t Random::UniformIndex(std::size_t n) {
  assert(n > 0);
  const auto range = static_cast<std::uint64_t>(n);
  // Lemire (2019): multiply into 128 bits and reject the few biased low words.
  Uint128 product = static_cast<Uint128>(NextBits()) * range;
  auto low = static_cast<std::uint64_t>(product);
  if (low < range) {
    const std::uint64_t threshold = (0 - range) % range;
    while (low < threshold) {
      product = static_cast<Uint128>(NextBits()) * range;
      low = static_cast<std::uint64_t>(product);
    }
  }
  return static_cast<std::size_t>(product >> 64);
}

}  // namespace relmap
