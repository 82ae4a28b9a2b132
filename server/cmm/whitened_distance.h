// The hot loop of the classifier: squared whitened distances ‖W(x_j − c)‖² for a
// batch of points. With W = L⁻¹ (Σ̃ = LLᵀ) this is the squared Mahalanobis
// distance. Raw pointers and no Eigen inside, so that the kernel can be compiled
// for several instruction sets without mixing Eigen's alignment assumptions.
#pragma once

namespace relmap::cmm {

struct WhiteningView {
  const double* matrix;  // rows × dimension, row-major
  int rows;
  int dimension;
  bool lower_triangular;  // W(i, k) = 0 for k > i: half the work
  const double* centre;   // c, `dimension` values
};

// out[j] = ‖W(x_j − c)‖² for the `count` points x_j = (X[j], X[j + stride], ...),
// i.e. X is column-major with leading dimension `stride` (a point's coordinates
// are `stride` apart). Each point's value is computed by the same sequence of
// operations whatever `count` is, so a result never depends on the batch size.
void SquaredWhitenedDistances(const WhiteningView& whitening, const double* points, int count,
                              int stride, double* out);

}  // namespace relmap::cmm
