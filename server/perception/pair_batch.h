// ComputePairCodes for many pairs at once, in structure-of-arrays form so that the compiler
// vectorises it: bitwise the same codes as the one-pair kernel in pair_features.h.
#pragma once

#include <cstddef>
#include <cstdint>

#include "perception/pair_features.h"

namespace relmap::perception {

// Up to kPairBatch pairs; lane l is the pair (p1, n1, p2, n2) of the l-th Add.
inline constexpr int kPairBatch = 64;

class PairBatch {
 public:
  bool full() const { return size_ == kPairBatch; }
  int size() const { return size_; }
  // `tag` is handed back by Codes; positions and normals have w = 0.
  void Add(const Eigen::Vector4f& p1, const Eigen::Vector4f& n1, const Eigen::Vector4f& p2,
           const Eigen::Vector4f& n2, std::size_t tag);
  // Computes the codes of every pair, then calls emit(tag, codes) for each and empties the
  // batch.
  template <typename Emit>
  void Flush(Emit&& emit) {
    Compute();
    for (int l = 0; l < size_; ++l) emit(tag_[l], codes_[l]);
    size_ = 0;
  }

 private:
  void Compute();

  int size_ = 0;
  // Coordinates by lane: p1, n1, p2, n2 as x, y, z arrays.
  alignas(16) float p1_[3][kPairBatch], n1_[3][kPairBatch], p2_[3][kPairBatch], n2_[3][kPairBatch];
  std::size_t tag_[kPairBatch];
  PairCodes codes_[kPairBatch];
};

}  // namespace relmap::perception
