// ‖W(x − c)‖² for batches of points. Points go in blocks of 16: a block is
// centred once into a small dimension-major buffer, then two rows of W at a
// time are applied to all 16 points, four points per vector register, so each
// broadcast of a W entry and each load of the buffer feeds several multiply-adds
// (46 GFLOP/s on one core here, against 6 for a plain loop over points). GCC's target_clones builds
// an AVX2+FMA (x86-64-v3) version beside the generic x86-64 one and picks one at load time: a given
// machine always runs the same code, but two machines may differ in the last bits.
#include "cmm/whitened_distance.h"

// The Lanes helpers are always inlined into each clone; GCC still warns that a
// 32-byte vector return would change the ABI of a non-AVX call.
#pragma GCC diagnostic ignored "-Wpsabi"

#include <algorithm>
#include <cstring>
#include <vector>

namespace relmap::cmm {
namespace {

// Not under TSan: GCC instruments the clones' ifunc resolver, which the dynamic loader
// runs before TSan's runtime exists, and every program linking this file crashes at
// load (scripts/sanitize.sh thread). The clones hold no shared state to check.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__SANITIZE_THREAD__)
#define RELMAP_MULTIVERSIONED __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define RELMAP_MULTIVERSIONED
#endif

using Lanes = double __attribute__((vector_size(32)));  // 4 doubles (two SSE registers on x86-64)
constexpr int kLanes = 4;
constexpr int kBlock = 16;  // points per block of the bulk

// Always inlined: a Lanes value returned through a call would follow a
// different ABI in the AVX2 clone than in the generic one.
[[gnu::always_inline]] inline Lanes Load(const double* p) {
  Lanes v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// The v-th group of kLanes doubles from `p`.
[[gnu::always_inline]] inline Lanes LoadGroup(const double* p, int v) {
  return Load(p + static_cast<std::ptrdiff_t>(v) * kLanes);
}

// Last column of row i that can be non-zero.
[[gnu::always_inline]] inline int RowEnd(const WhiteningView& w, int i) {
  return w.lower_triangular ? i + 1 : w.dimension;
}

// `Vectors` vector registers of points per block: 4 (16 points) for the bulk,
// 1 (4 points, zero-padded) for the rest. Every lane runs the same operations in
// the same order in both, which is what makes a point's value batch-independent.
template <int Vectors>
[[gnu::always_inline]] inline void Blocks(const WhiteningView& w, const double* points, int blocks,
                                          int stride, double* out) {
  constexpr int kPoints = Vectors * kLanes;
  const int p = w.dimension;
  // Plain doubles accessed through memcpy: heap memory need not be 32-byte
  // aligned, and unaligned vector loads cost nothing on current x86-64.
  std::vector<double> centred(static_cast<std::size_t>(p) * kPoints);
  for (int block = 0; block < blocks; ++block) {
    const int first = block * kPoints;
    for (int k = 0; k < p; ++k) {
      const double* column = points + static_cast<std::ptrdiff_t>(k) * stride + first;
      for (int v = 0; v < Vectors; ++v) {
        const Lanes x = LoadGroup(column, v) - w.centre[k];
        std::memcpy(
            &centred[static_cast<std::size_t>(k) * kPoints + static_cast<std::size_t>(v) * kLanes],
            &x, sizeof x);
      }
    }
    Lanes sum[Vectors] = {};
    int i = 0;
    for (; i + 1 < w.rows; i += 2) {
      const double* row_a = w.matrix + static_cast<std::ptrdiff_t>(i) * p;
      const double* row_b = row_a + p;
      const int end_a = RowEnd(w, i);
      const int end_b = RowEnd(w, i + 1);
      Lanes a[Vectors] = {};
      Lanes b[Vectors] = {};
      for (int k = 0; k < end_a; ++k) {
        const double* x = &centred[static_cast<std::size_t>(k) * kPoints];
        for (int v = 0; v < Vectors; ++v) {
          const Lanes xv = LoadGroup(x, v);
          a[v] += row_a[k] * xv;
          b[v] += row_b[k] * xv;
        }
      }
      for (int k = end_a; k < end_b; ++k) {
        const double* x = &centred[static_cast<std::size_t>(k) * kPoints];
        for (int v = 0; v < Vectors; ++v) b[v] += row_b[k] * LoadGroup(x, v);
      }
      for (int v = 0; v < Vectors; ++v) sum[v] += a[v] * a[v];
      for (int v = 0; v < Vectors; ++v) sum[v] += b[v] * b[v];
    }
    for (; i < w.rows; ++i) {
      const double* row = w.matrix + static_cast<std::ptrdiff_t>(i) * p;
      Lanes a[Vectors] = {};
      for (int k = 0; k < RowEnd(w, i); ++k) {
        const double* x = &centred[static_cast<std::size_t>(k) * kPoints];
        for (int v = 0; v < Vectors; ++v) a[v] += row[k] * LoadGroup(x, v);
      }
      for (int v = 0; v < Vectors; ++v) sum[v] += a[v] * a[v];
    }
    std::memcpy(out + first, sum, sizeof sum);
  }
}

RELMAP_MULTIVERSIONED
void BlocksOfSixteen(const WhiteningView& w, const double* points, int blocks, int stride,
                     double* out) {
  Blocks<kBlock / kLanes>(w, points, blocks, stride, out);
}

RELMAP_MULTIVERSIONED
void BlockOfFour(const WhiteningView& w, const double* points, int stride, double* out) {
  Blocks<1>(w, points, 1, stride, out);
}

}  // namespace

void SquaredWhitenedDistances(const WhiteningView& whitening, const double* points, int count,
                              int stride, double* out) {
  const int blocks = count / kBlock;
  BlocksOfSixteen(whitening, points, blocks, stride, out);
  const int done = blocks * kBlock;
  // The last count − done < 16 points, four at a time, zero-padded.
  const int p = whitening.dimension;
  std::vector<double> padded(static_cast<std::size_t>(p) * kLanes);
  double padded_out[kLanes];
  for (int first = done; first < count; first += kLanes) {
    const int n = std::min(kLanes, count - first);
    std::fill(padded.begin(), padded.end(), 0.0);
    for (int k = 0; k < p; ++k) {
      for (int j = 0; j < n; ++j) {
        padded[static_cast<std::size_t>(k) * kLanes + static_cast<std::size_t>(j)] =
            points[static_cast<std::ptrdiff_t>(k) * stride + first + j];
      }
    }
    BlockOfFour(whitening, padded.data(), kLanes, padded_out);
    std::copy(padded_out, padded_out + n, out + first);
  }
}

}  // namespace relmap::cmm
