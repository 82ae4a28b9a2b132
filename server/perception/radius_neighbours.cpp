// Uniform-grid radius search: points sorted by cell, each cell's points tested against the
// 3x3x3 block of cells around it, in parallel over cells.
#include "perception/radius_neighbours.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace relmap::perception {
namespace {

// The sorted keys of the 3 x-adjacent cells of one (dz, dy) row of a 3x3x3 block are
// consecutive, so each of the 9 rows is one contiguous range of the sorted points.
struct Block {
  std::array<std::uint32_t, 9> first, last;
};

}  // namespace

RadiusNeighbours FindRadiusNeighbours(const std::vector<Eigen::Vector3f>& positions, float radius,
                                      int threads) {
  RadiusNeighbours table;
  const std::size_t n = positions.size();
  table.begin.assign(n + 1, 0);
  if (n == 0) return table;

  // Cells slightly wider than the radius, so that float rounding of the cell coordinate
  // never puts two points closer than `radius` two cells apart. One empty cell of padding
  // on each side keeps the ±1 rows and columns inside the grid (no wrap-around of keys).
  const double cell = 1.001 * static_cast<double>(radius);
  Eigen::Vector3f lo = positions[0], hi = positions[0];
  for (const Eigen::Vector3f& p : positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const auto coordinate = [&](float v, int axis) {
    return static_cast<std::uint64_t>(std::floor((static_cast<double>(v) - lo[axis]) / cell)) + 1;
  };
  const std::uint64_t nx = coordinate(hi.x(), 0) + 2, ny = coordinate(hi.y(), 1) + 2;
  std::vector<std::uint64_t> key_of(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3f& p = positions[i];
    key_of[i] = (coordinate(p.z(), 2) * ny + coordinate(p.y(), 1)) * nx + coordinate(p.x(), 0);
  }
  table.order.resize(n);
  std::iota(table.order.begin(), table.order.end(), 0u);
  std::stable_sort(table.order.begin(), table.order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return key_of[a] < key_of[b]; });
  std::vector<std::uint64_t> keys(n);
  std::vector<float> x(n), y(n), z(n);  // structure of arrays: the distance loop vectorises
  for (std::size_t r = 0; r < n; ++r) {
    keys[r] = key_of[table.order[r]];
    const Eigen::Vector3f& p = positions[table.order[r]];
    x[r] = p.x(), y[r] = p.y(), z[r] = p.z();
  }

  // Occupied cells: [cell_start[c], cell_start[c + 1]) of the sorted points.
  std::vector<std::uint32_t> cell_start;
  for (std::size_t r = 0; r < n; ++r) {
    if (r == 0 || keys[r] != keys[r - 1]) cell_start.push_back(static_cast<std::uint32_t>(r));
  }
  const auto cells = static_cast<std::ptrdiff_t>(cell_start.size());
  cell_start.push_back(static_cast<std::uint32_t>(n));
  const auto block_of = [&](std::uint64_t key) {
    Block block;
    int row = 0;
    for (int dz = -1; dz <= 1; ++dz) {
      for (int dy = -1; dy <= 1; ++dy, ++row) {
        const std::uint64_t centre = key + (dz * static_cast<std::int64_t>(ny) + dy) * nx;
        block.first[row] = static_cast<std::uint32_t>(
            std::lower_bound(keys.begin(), keys.end(), centre - 1) - keys.begin());
        block.last[row] = static_cast<std::uint32_t>(
            std::upper_bound(keys.begin(), keys.end(), centre + 1) - keys.begin());
      }
    }
    return block;
  };
  // KdTreeFLANN compares with static_cast<float>(radius * radius), radius a double.
  const auto r2 = static_cast<float>(static_cast<double>(radius) * radius);
  const auto sq_distance = [&](std::size_t q, std::size_t p) {
    return FlannSquaredDistance(x[q], y[q], z[q], x[p], y[p], z[p]);
  };
  // Calls visit(q, block) for every point q of occupied cell c.
  const auto for_points_of_cell = [&](std::ptrdiff_t c, auto&& visit) {
    const auto uc = static_cast<std::size_t>(c);
    const Block block = block_of(keys[cell_start[uc]]);
    for (std::size_t q = cell_start[uc]; q < cell_start[uc + 1]; ++q) visit(q, block);
  };

  // Pass 1 counts, pass 2 fills the rows in place: no per-chunk buffers to concatenate
  // (fresh memory costs page faults every frame), and the table does not depend on the
  // thread count or schedule. The distances are cheap to compute twice.
  std::vector<std::size_t> count(n, 0);
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads)
  for (std::ptrdiff_t c = 0; c < cells; ++c) {
    for_points_of_cell(c, [&](std::size_t q, const Block& block) {
      std::size_t found = 0;
      for (int row = 0; row < 9; ++row) {
        for (std::size_t p = block.first[row]; p < block.last[row]; ++p) {
          found += sq_distance(q, p) < r2 ? 1 : 0;
        }
      }
      count[q] = found;
    });
  }
  for (std::size_t r = 0; r < n; ++r) table.begin[r + 1] = table.begin[r] + count[r];
  table.neighbour.resize(table.begin[n]);
#pragma omp parallel num_threads(threads)
  {
    std::vector<std::uint32_t> kept;  // one row, compacted
#pragma omp for schedule(dynamic, 16)
    for (std::ptrdiff_t c = 0; c < cells; ++c) {
      for_points_of_cell(c, [&](std::size_t q, const Block& block) {
        std::size_t found = 0;
        for (int row = 0; row < 9; ++row) {
          // Branch-free compaction (about a third of the candidates are kept: a branch per
          // candidate would mispredict); the slot past the last kept one is scratch.
          kept.resize(found + block.last[row] - block.first[row] + 1);
          for (std::size_t p = block.first[row]; p < block.last[row]; ++p) {
            kept[found] = static_cast<std::uint32_t>(p);
            found += sq_distance(q, p) < r2 ? 1 : 0;
          }
        }
        std::copy_n(kept.begin(), found,
                    table.neighbour.begin() + static_cast<std::ptrdiff_t>(table.begin[q]));
      });
    }
  }
  return table;
}

}  // namespace relmap::perception
