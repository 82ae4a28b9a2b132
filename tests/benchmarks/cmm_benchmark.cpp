// Benchmarks of the classifier on one core: the distance kernel, batch
// prediction of a frame's supervoxels, and one IAGMM update, at p = 48.
#include <benchmark/benchmark.h>

#include "cmm/collaborative_mixture_models.h"
#include "cmm/random.h"
#include "datasets/synthetic_problems.h"

namespace relmap::cmm {
namespace {

constexpr int kDimension = 48;

Eigen::MatrixXd UniformPoints(int rows, std::uint64_t seed) {
  Random random(seed);
  Eigen::MatrixXd points(rows, kDimension);
  for (Eigen::Index i = 0; i < points.size(); ++i) points.data()[i] = random.UniformUnit();
  return points;
}

// ‖L⁻¹(x − μ)‖² of N points under one full 48-d component: the inner loop of
// everything else (p²/2 = 1152 multiply-adds per point).
void BM_SquaredMahalanobisKernel(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  Dataset data(kDimension);
  const Eigen::MatrixXd samples = UniformPoints(200, 1);
  for (int i = 0; i < 200; ++i) data.Append(samples.row(i).transpose(), 0);
  std::vector<int> all(200);
  for (int i = 0; i < 200; ++i) all[i] = i;
  const Component c = Component::FromSamples(0, all, data, CmmConfig{});
  const Eigen::MatrixXd points = UniformPoints(n, 2);
  std::vector<double> out(n);
  for (auto _ : state) {
    c.SquaredMahalanobis(points.data(), n, n, out.data());
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * n);
  state.counters["GFLOP/s"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * n * kDimension * (kDimension + 1),
      benchmark::Counter::kIsRate, benchmark::Counter::kIs1000);
}
BENCHMARK(BM_SquaredMahalanobisKernel)->Arg(1)->Arg(16)->Arg(1000)->Arg(5000);

}  // namespace
}  // namespace relmap::cmm

BENCHMARK_MAIN();
