// Explicit draws from std::mt19937_64 (see seeded_random.h for why).
#include "seeded_random.h"

#include <cmath>
#include <numbers>

#include "common/random.h"

namespace relmap::sim {
SeededRandom::SeededRandom(std::uint64_t seed, std::uint64_t stream)
    : engine_(SplitMix64At(seed ^ SplitMix64At(stream))) {}

double SeededRandom::Uniform01() { return UnitFromBits(engine_()); }

double SeededRandom::Uniform(double lo, double hi) { return lo + (hi - lo) * Uniform01(); }

std::uint64_t SeededRandom::Below(std::uint64_t n) {
  // Reject the top partial block of the 2^64 range so every residue is equally likely.
  const std::uint64_t limit = ~std::uint64_t{0} - (~std::uint64_t{0} % n);
  std::uint64_t x = engine_();
  while (x >= limit) x = engine_();
  return x % n;
}

double SeededRandom::Gaussian() {
  const double u1 = 1.0 - Uniform01();  // (0, 1]: log is finite
  const double u2 = Uniform01();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2 * std::numbers::pi * u2);
}

Eigen::Quaterniond SeededRandom::Rotation() {
  const double u1 = Uniform01(), u2 = Uniform01(), u3 = Uniform01();
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
  const double turn2 = 2 * std::numbers::pi * u2, turn3 = 2 * std::numbers::pi * u3;
  return Eigen::Quaterniond(a * std::sin(turn2), a * std::cos(turn2), b * std::sin(turn3),
                            b * std::cos(turn3));
}

}  // namespace relmap::sim
