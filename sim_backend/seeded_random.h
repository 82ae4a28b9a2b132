// The simulator's random numbers: the same seed gives the same scene, push and
// noise on every machine and standard library.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <random>

namespace relmap::sim {

// std::mt19937_64's output sequence is fixed by the C++ standard, but
// std::uniform_real_distribution, std::normal_distribution and friends are
// implementation-defined algorithms (libstdc++ and libc++ give different numbers
// for the same engine), so every draw here is explicit arithmetic on the engine's
// 64-bit words.
class SeededRandom {
 public:
  // `stream` separates independent uses of one seed (respawn, push, noise).
  explicit SeededRandom(std::uint64_t seed, std::uint64_t stream = 0);

  // Uniform in [0, 1), 53 random bits.
  double Uniform01();
  // Uniform in [lo, hi) (lo when hi == lo).
  double Uniform(double lo, double hi);
  // Uniform in {0, ..., n - 1}, n >= 1, without modulo bias.
  std::uint64_t Below(std::uint64_t n);
  // Standard normal, Box-Muller.
  double Gaussian();
  // A uniformly distributed rotation (Shoemake's method).
  Eigen::Quaterniond Rotation();

 private:
  std::mt19937_64 engine_;
};

}  // namespace relmap::sim
