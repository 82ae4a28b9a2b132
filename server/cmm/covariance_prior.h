// The session-wide quantities of the pooled covariance prior (§3.2 of
// docs/method.md, CovarianceEstimate::kPooledPrior): the prior scale Ψ of every
// component's covariance, its pseudo-sample count κ, the variance floor φ, and
// the background density B of the calibrated prediction (§3.3).
#pragma once

#include <Eigen/Core>

#include "cmm/config.h"
#include "cmm/dataset.h"

namespace relmap::cmm {

struct CovariancePrior {
  int computed_from = 0;        // the first this many samples of the dataset; 0 = none yet
  Eigen::MatrixXd scale;        // Ψ
  double pseudo_samples = 0.0;  // κ
  double floor = 0.0;           // φ, added to the diagonal of every component's covariance

  // B(x) = N(x; mean, 4Σ_t), Σ_t the dataset's total covariance shrunk like Ψ:
  // twice the spread of all the data, so that it is negligible next to the
  // class mixtures where there are data and dominates far from them.
  Eigen::VectorXd background_mean;
  // L⁻¹ of the background covariance (lower triangular, row-major for the kernel).
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> background_whitening;
  double background_log_normaliser = 0.0;

  // log B of the `count` points of a column-major matrix with leading dimension
  // `stride` (the layout of Dataset and of Evaluate's batches).
  void BackgroundLogDensity(const double* points, int count, int stride, double* out) const;
};

// The prior after the first `count` samples of `data` (count >= 1):
// Ψ = OAS(Σ_local) (Chen et al., 2010, eq. 23), Σ_local = ½·mean of dᵢdᵢᵀ over
// the differences dᵢ between each sample and its nearest neighbour of the same
// class (the difference-based variance estimator: the covariance of the data
// at the scale of a neighbourhood, not of a whole class, which in XOR blobs or
// rings spans several clusters); the total covariance when no class has two
// samples yet; (‖x̄‖²/p)·I, or I, while every sample is the same point. OAS
// keeps Ψ positive definite whenever the data vary at all. φ = variance_floor · tr(Ψ)/p.
// Deterministic: the same data give the same bits, which is how a snapshot restores it.
CovariancePrior ComputeCovariancePrior(const Dataset& data, int count, const CmmConfig& config);

// Whether the prior is recomputed when the dataset reaches `size` samples: at
// every power of two, so that Ψ follows the data while refitting every
// component costs O(p²) amortised per sample.
inline bool IsPriorCheckpoint(int size) { return size > 0 && (size & (size - 1)) == 0; }

// The sample count the prior of a dataset of `size` samples was computed from:
// the largest power of two <= size (0 for an empty dataset).
int PriorSampleCount(int size);

// The OAS shrinkage of a sample covariance `s` estimated from `n` samples,
// towards (tr s/p)·I: (1 − ρ)s + ρ(tr s/p)I with
// ρ = min(1, ((1 − 2/p) tr(s²) + tr²(s)) / ((n + 1 − 2/p)(tr(s²) − tr²(s)/p))).
Eigen::MatrixXd OracleApproximatingShrinkage(const Eigen::MatrixXd& s, double n);

}  // namespace relmap::cmm
