// Benchmarks of the classifier on one core: the distance kernel, batch
// prediction of a frame's supervoxels, and one IAGMM update, at p = 48.
#include <benchmark/benchmark.h>

#include "cmm/collaborative_mixture_models.h"
#include "cmm/snapshot.h"
#include "common/random.h"
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

// A model with exactly K full-rank components (60 samples each, both classes),
// restored from a snapshot, so that prediction cost can be read against K.
CollaborativeMixtureModels ModelWithComponents(int k) {
  constexpr int kPerComponent = 60;
  CmmSnapshot s;
  s.dimension = kDimension;
  Random random(3);
  for (int c = 0; c < k; ++c) {
    const int label = c % 2;
    Eigen::VectorXd centre(kDimension);
    for (int d = 0; d < kDimension; ++d) centre[d] = random.UniformUnit();
    Eigen::MatrixXd points(kDimension, kPerComponent);
    ComponentSnapshot cs;
    for (int j = 0; j < kPerComponent; ++j) {
      for (int d = 0; d < kDimension; ++d) points(d, j) = centre[d] + 0.05 * random.UniformUnit();
      cs.samples.push_back(static_cast<int>(s.labels.size()));
      s.labels.push_back(static_cast<std::int8_t>(label));
      s.features.insert(s.features.end(), points.col(j).data(), points.col(j).data() + kDimension);
    }
    const Eigen::VectorXd mean = points.rowwise().mean();
    points.colwise() -= mean;
    const Eigen::MatrixXd scatter = points * points.transpose();
    cs.mean.assign(mean.data(), mean.data() + kDimension);
    cs.scatter.assign(scatter.data(), scatter.data() + scatter.size());
    s.components[label].push_back(std::move(cs));
  }
  for (int label = 0; label < 2; ++label) {
    for (auto& c : s.components[label])
      c.weight = 1.0 / static_cast<double>(s.components[label].size());
  }
  return CollaborativeMixtureModels::Restore(s).value();
}

// Eq. (class_est) plus the confidence quantities for N supervoxels of a frame.
void BM_EvaluateFrame(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const int k = static_cast<int>(state.range(1));
  const CollaborativeMixtureModels model = ModelWithComponents(k);
  const Eigen::MatrixXd points = UniformPoints(n, 4);
  for (auto _ : state) benchmark::DoNotOptimize(model.Evaluate(points));
  state.counters["K"] = k;
}
BENCHMARK(BM_EvaluateFrame)
    ->ArgsProduct({{100, 1000, 5000}, {2, 10, 40}})
    ->Unit(benchmark::kMillisecond);

// One IAGMM update (add, SPLIT/MERGE, random re-check) at dataset size n, on the
// 48-d XOR-blobs stream of the demo. Each iteration adds one of the next 64
// samples to a fresh copy of the trained model (the copy is not timed).
void BM_Update(benchmark::State& state, Variant variant, double regularization) {
  const int n = static_cast<int>(state.range(0));
  datasets::ProblemOptions options;
  options.problem = datasets::Problem::kXorBlobs;
  options.dimension = kDimension;
  options.samples = n + 64;
  options.seed = 1;
  const datasets::LabelledSamples stream = datasets::MakeProblem(options);
  CmmConfig config = CmmConfig::ForVariant(variant);
  config.regularization = regularization;  // the ridge of corrected_v1; ignored by the others
  auto trained = CollaborativeMixtureModels::Create(config, kDimension).value();
  for (int i = 0; i < n; ++i)
    (void)trained.Add(stream.features.row(i).transpose(), stream.labels[i]);
  trained.LogLikelihood();  // warm the caches as they are in a running session

  int next = 0;
  for (auto _ : state) {
    state.PauseTiming();
    CollaborativeMixtureModels model = trained;
    const int row = n + next;
    next = (next + 1) % 64;
    state.ResumeTiming();
    benchmark::DoNotOptimize(model.Add(stream.features.row(row).transpose(), stream.labels[row]));
  }
  state.counters["K"] = trained.component_count(0) + trained.component_count(1);
}
BENCHMARK_CAPTURE(BM_Update, corrected, Variant::kCorrected, 1e-6)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(5000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Update, corrected_v1, Variant::kCorrectedV1, 1e-6)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(5000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Update, corrected_v1_lambda_1e_3, Variant::kCorrectedV1, 1e-3)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(5000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Update, paper2018, Variant::kPaper2018, 1e-6)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(5000)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace relmap::cmm

BENCHMARK_MAIN();
