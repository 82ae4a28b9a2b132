// Procedural textures: wood growth rings perturbed by value noise, and a 3-D
// checkerboard. Deterministic functions of the local point (no state, no seed).
#include "textures.h"

#include <cmath>
#include <cstdint>
#include <numbers>

namespace relmap::sim {
namespace {

Eigen::Vector3d ToUnit(const Rgb8& c) { return Eigen::Vector3d(c[0], c[1], c[2]) / 255.0; }

// A pseudo-random value in [0, 1) for an integer lattice point.
double LatticeValue(std::int64_t x, std::int64_t y, std::int64_t z) {
  std::uint64_t h = static_cast<std::uint64_t>(x) * 0x8da6b343ULL ^
                    static_cast<std::uint64_t>(y) * 0xd8163841ULL ^
                    static_cast<std::uint64_t>(z) * 0xcb1ab31fULL;
  h ^= h >> 29;
  h *= 0xbf58476d1ce4e5b9ULL;
  h ^= h >> 32;
  return static_cast<double>(h >> 11) * 0x1.0p-53;
}

double Smooth(double t) { return t * t * (3.0 - 2.0 * t); }

// Value noise: the lattice values trilinearly blended with a smoothstep, in [0, 1).
double ValueNoise(const Eigen::Vector3d& p) {
  const Eigen::Vector3d cell = p.array().floor();
  const Eigen::Vector3d f = p - cell;
  const auto ix = static_cast<std::int64_t>(cell.x()), iy = static_cast<std::int64_t>(cell.y()),
             iz = static_cast<std::int64_t>(cell.z());
  const double u = Smooth(f.x()), v = Smooth(f.y()), w = Smooth(f.z());
  double value = 0;
  for (int dz = 0; dz < 2; ++dz) {
    for (int dy = 0; dy < 2; ++dy) {
      for (int dx = 0; dx < 2; ++dx) {
        const double weight = (dx ? u : 1 - u) * (dy ? v : 1 - v) * (dz ? w : 1 - w);
        value += weight * LatticeValue(ix + dx, iy + dy, iz + dz);
      }
    }
  }
  return value;
}

// Growth rings around the local x axis (offset from it, so a box's face shows
// arcs rather than a bullseye), radius perturbed by low-frequency noise and the
// ring profile sharpened: 0 = early wood, 1 = late wood.
double WoodGrain(const Eigen::Vector3d& p, double ring_spacing) {
  const double stretch = 1.0 / ring_spacing;
  const Eigen::Vector3d q(p.x() * 0.15 * stretch, p.y() * stretch, p.z() * stretch);
  const double radius = std::hypot(p.y() + 7.3 * ring_spacing, p.z() - 31.0 * ring_spacing);
  const double rings = radius / ring_spacing + 1.6 * ValueNoise(q * 0.35) + 0.3 * ValueNoise(q);
  const double profile = 0.5 + 0.5 * std::sin(2.0 * std::numbers::pi * rings);
  return profile * profile * profile * (0.75 + 0.25 * ValueNoise(q * 2.0));
}

// Cubes of side `scale`, the lattice shifted off the origin so that faces lying
// on a lattice plane (a box's face at a round coordinate) do not flicker.
double Checker(const Eigen::Vector3d& p, double scale) {
  const Eigen::Vector3d q = (p / scale).array() + 0.2371;
  const auto sum =
      static_cast<std::int64_t>(std::floor(q.x()) + std::floor(q.y()) + std::floor(q.z()));
  return (sum & 1) != 0 ? 1.0 : 0.0;
}

}  // namespace

Eigen::Vector3d Albedo(const Material& material, const Eigen::Vector3d& local) {
  Eigen::Vector3d base = ToUnit(material.color);
  double t = 0;
  switch (material.texture) {
    case TextureKind::kNone:
      return base;
    case TextureKind::kWood:
      t = WoodGrain(local, material.texture_scale);
      break;
    case TextureKind::kChecker:
      t = Checker(local, material.texture_scale);
      break;
  }
  return (1.0 - t) * base + t * ToUnit(material.texture_color);
}

}  // namespace relmap::sim
