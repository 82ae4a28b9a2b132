// Append-only storage of the labelled samples.
#include "cmm/dataset.h"

#include <algorithm>

namespace relmap::cmm {

void Dataset::Append(const Eigen::Ref<const Eigen::VectorXd>& x, int label) {
  if (size_ == features_.rows()) {
    const Eigen::Index capacity = std::max<Eigen::Index>(64, 2 * features_.rows());
    Eigen::MatrixXd grown(capacity, dimension_);
    grown.topRows(size_) = features_.topRows(size_);
    features_.swap(grown);
  }
  features_.row(size_) = x.transpose();
  labels_.push_back(static_cast<std::int8_t>(label));
  ++counts_[label];
  ++size_;
}

}  // namespace relmap::cmm
