// The labelled dataset S of a model: append-only, one row per sample.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace relmap::cmm {

class Dataset {
 public:
  explicit Dataset(int dimension) : dimension_(dimension), features_(0, dimension) {}

  // Appends (x, label); the caller has validated both.
  void Append(const Eigen::Ref<const Eigen::VectorXd>& x, int label);

  int dimension() const { return dimension_; }
  int size() const { return size_; }
  int count(int label) const { return counts_[label]; }
  int label(int index) const { return labels_[index]; }
  const std::vector<std::int8_t>& labels() const { return labels_; }

  // Row `index` as a column vector (a strided view into the storage).
  auto sample(int index) const { return features_.row(index).transpose(); }
  // The first `size()` rows: column-major, leading dimension stride().
  auto features() const { return features_.topRows(size_); }
  const double* data() const { return features_.data(); }
  int stride() const { return static_cast<int>(features_.rows()); }

 private:
  int dimension_;
  int size_ = 0;
  // Column-major with spare rows, doubled when full, so that one coordinate of
  // consecutive samples is contiguous (what the distance kernel wants).
  Eigen::MatrixXd features_;
  std::vector<std::int8_t> labels_;
  std::array<int, 2> counts_{0, 0};
};

}  // namespace relmap::cmm
