// Google Benchmark of every perception stage on the real clouds of ../shared/data/real and
// on synthetic 640x480 and 320x240 tabletops: decode, supervoxels (with and without the
// pre-voxelisation), features (shared and exact FPFH), the whole frame, change detection.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "perception/change_detector.h"
#include "perception/decode.h"
#include "perception/features.h"
#include "perception/frame.h"
#include "perception/synthetic_tabletop.h"

namespace rp = relmap::perception;

namespace {

struct Input {
  std::string name;
  std::string pcd;  // bytes of the file; empty for synthetic clouds
  rp::Cloud cloud;
};

std::vector<Input> Inputs() {
  std::vector<Input> inputs;
  const std::string dir = RELMAP_BENCHMARK_DATA_DIR;
  for (const char* name : {"table_scene_mug_stereo_textured", "milk_cartoon_all_small_clorox",
                           "kinect_static_seq_1", "kinect_static_seq_2", "kinect_static_seq_3"}) {
    const std::string path = dir + "/" + name + ".pcd";
    if (!std::filesystem::exists(path)) continue;
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    auto cloud = rp::DecodePcd(bytes.str());
    if (cloud.ok()) inputs.push_back({name, bytes.str(), *cloud});
  }
  for (std::uint32_t w : {640u, 320u}) {
    rp::SyntheticTabletopOptions options;
    options.width = w, options.height = w * 3 / 4;
    inputs.push_back(
        {"synthetic_" + std::to_string(w), "", rp::MakeSyntheticTabletop(options).cloud});
  }
  return inputs;
}

void Decode(benchmark::State& state, const Input* in) {
  for (auto _ : state) benchmark::DoNotOptimize(rp::DecodePcd(in->pcd));
}

void Supervoxels(benchmark::State& state, const Input* in, bool prevoxelise) {
  rp::SupervoxelConfig config;
  config.prevoxelise = prevoxelise;
  for (auto _ : state) {
    auto seg = rp::ExtractSupervoxels(in->cloud, config);
    state.counters["supervoxels"] = static_cast<double>(seg->supervoxels.size());
  }
}

void Features(benchmark::State& state, const Input* in, rp::FpfhScheme scheme, int threads) {
  const auto seg = rp::ExtractSupervoxels(in->cloud, rp::SupervoxelConfig{});
  rp::FeatureConfig config;
  config.fpfh_scheme = scheme;
  for (auto _ : state)
    benchmark::DoNotOptimize(rp::ComputeFeatures(in->cloud, *seg, config, threads));
}

void WholeFrame(benchmark::State& state, const Input* in, bool naive) {
  rp::PerceptionConfig config;
  if (naive) {  // the "before" pipeline: every raw point into VCCS, §2 literally, 1 thread
    config.supervoxels.prevoxelise = false;
    config.features.fpfh_scheme = rp::FpfhScheme::kExactUnion;
    config.threads = 1;
  }
  for (auto _ : state) benchmark::DoNotOptimize(rp::BuildFrame(in->cloud, config));
}

void ChangeDetection(benchmark::State& state, const Input* before, const Input* after,
                     rp::ChangeMethod method) {
  // The first supervoxel as the target, its object found among the frame's (as the
  // server's path judges it, docs/method.md §5.1).
  const auto seg = rp::ExtractSupervoxels(before->cloud, rp::SupervoxelConfig{});
  rp::ChangeDetectorConfig config;
  config.method = method;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        rp::DetectChange(before->cloud, after->cloud, seg->supervoxels, 0, config));
  }
}

}  // namespace

int main(int argc, char** argv) {
  static const std::vector<Input> inputs = Inputs();
  for (const Input& in : inputs) {
    const std::string n = in.name;
    if (!in.pcd.empty()) benchmark::RegisterBenchmark(("Decode/" + n).c_str(), Decode, &in);
    benchmark::RegisterBenchmark(("Supervoxels/prevoxelised/" + n).c_str(), Supervoxels, &in, true);
    benchmark::RegisterBenchmark(("Supervoxels/raw_points/" + n).c_str(), Supervoxels, &in, false);
    benchmark::RegisterBenchmark(("Features/shared/" + n).c_str(), Features, &in,
                                 rp::FpfhScheme::kSharedVoxels, 2);
    benchmark::RegisterBenchmark(("Features/exact_1thread/" + n).c_str(), Features, &in,
                                 rp::FpfhScheme::kExactUnion, 1)
        ->Iterations(1);
    benchmark::RegisterBenchmark(("Frame/optimised/" + n).c_str(), WholeFrame, &in, false);
    benchmark::RegisterBenchmark(("Frame/naive/" + n).c_str(), WholeFrame, &in, true)
        ->Iterations(1);
  }
  for (std::size_t i = 0; i + 1 < inputs.size(); ++i) {
    if (inputs[i].name.rfind("kinect_static_seq", 0) == 0 &&
        inputs[i + 1].name.rfind("kinect_static_seq", 0) == 0) {
      for (const rp::ChangeMethod method :
           {rp::ChangeMethod::kVisibility, rp::ChangeMethod::kPaper2018}) {
        benchmark::RegisterBenchmark(
            ("ChangeDetection/" + std::string(rp::ChangeMethodName(method)) + "/" + inputs[i].name +
             "_to_next")
                .c_str(),
            ChangeDetection, &inputs[i], &inputs[i + 1], method);
      }
    }
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
