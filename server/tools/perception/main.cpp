// relmap-perception: times the perception pipeline on one cloud (one JSON line), renders
// its segmentation, or runs the change detector on two clouds.
//
//   relmap-perception <cloud.pcd | synthetic:WxH> [--voxel 0.008] [--seed 0.05] [--repeat 5]
//       [--png seg.png] [--fpfh shared_voxels|exact_union|raw_points]
//       [--colour corrected|paper2018] [--raw-spacing 0.004]
//       [--raw-normal-radius 0.01] [--no-prevoxelise] [--threads 2]
//       [--fpfh-deviation] [--feature-stats] [--stride 2]
//   relmap-perception --change before.pcd after.pcd --target-point x,y,z
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "perception/change_detector.h"
#include "perception/colour_histogram.h"
#include "perception/decode.h"
#include "perception/fpfh.h"
#include "perception/frame.h"
#include "perception/synthetic_tabletop.h"
#include "segmentation_png.h"

namespace rp = relmap::perception;

namespace {

int Fail(const std::string& message) {
  std::cerr << "relmap-perception: " << message << "\n";
  return 1;
}

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

bool ReadFile(const std::string& path, std::string& bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream s;
  s << in.rdbuf();
  bytes = s.str();
  return true;
}

// The packed encoding of a cloud (DecodePacked's input), decoded each repeat like an upload.
std::string PackedBytes(const std::vector<rp::CloudPoint>& points) {
  std::string bytes;
  for (const rp::CloudPoint& p : points) {
    const char* raw = reinterpret_cast<const char*>(&p.x);
    bytes.append(raw, 12);
    bytes.append({static_cast<char>(p.r), static_cast<char>(p.g), static_cast<char>(p.b),
                  static_cast<char>(p.a)});
  }
  return bytes;
}

// "synthetic:640x480" -> the packed encoding of a synthetic tabletop.
bool SyntheticBytes(const std::string& spec, std::uint32_t& w, std::uint32_t& h,
                    std::string& bytes) {
  if (std::sscanf(spec.c_str(), "synthetic:%ux%u", &w, &h) != 2) return false;
  rp::SyntheticTabletopOptions options;
  options.width = w, options.height = h;
  bytes = PackedBytes(rp::MakeSyntheticTabletop(options).cloud.points());
  return true;
}

// Every `stride`-th column and row of an organized PCD file, packed: what a camera of
// 1/stride the resolution sees of the same scene (320x240 from a 640x480 recording).
bool DecimatedBytes(const std::string& pcd, std::uint32_t stride, std::uint32_t& w,
                    std::uint32_t& h, std::string& bytes) {
  auto cloud = rp::DecodePcd(pcd);
  if (!cloud.ok() || !cloud->organized()) return false;
  const std::vector<rp::CloudPoint> points = cloud->points();
  w = cloud->width() / stride, h = cloud->height() / stride;
  std::vector<rp::CloudPoint> kept;
  for (std::uint32_t v = 0; v < h; ++v) {
    for (std::uint32_t u = 0; u < w; ++u) {
      kept.push_back(points[static_cast<std::size_t>(v) * stride * cloud->width() + u * stride]);
    }
  }
  bytes = PackedBytes(kept);
  return true;
}

// The mean feature over the frame's finite rows, and the largest value of each of its three
// FPFH blocks: how peaked the frame's FPFH are, comparable with another pipeline's means.
std::string FeatureStatsJson(const rp::FeatureMatrix& features) {
  Eigen::RowVectorXd sum = Eigen::RowVectorXd::Zero(rp::kFeatureDims);
  std::size_t rows = 0;
  for (Eigen::Index r = 0; r < features.values.rows(); ++r) {
    if (features.non_finite[static_cast<std::size_t>(r)] > 0) continue;
    sum += features.values.row(r);
    ++rows;
  }
  const Eigen::RowVectorXd mean = sum / static_cast<double>(std::max<std::size_t>(rows, 1));
  std::string json = ",\"mean_feature\":[";
  char number[32];
  for (int d = 0; d < rp::kFeatureDims; ++d) {
    std::snprintf(number, sizeof(number), "%s%.3f", d ? "," : "", mean[d]);
    json += number;
  }
  json += "],\"fpfh_block_max\":[";
  for (int block = 0; block < 3; ++block) {
    const double peak =
        mean.segment(rp::kColourDims + block * rp::kFpfhBins, rp::kFpfhBins).maxCoeff();
    std::snprintf(number, sizeof(number), "%s%.3f", block ? "," : "", peak);
    json += number;
  }
  return json + "]";
}

int Change(int argc, char** argv) {
  if (argc != 6 || std::string(argv[4]) != "--target-point") {
    return Fail("usage: relmap-perception --change before.pcd after.pcd --target-point x,y,z");
  }
  float x, y, z;
  if (std::sscanf(argv[5], "%f,%f,%f", &x, &y, &z) != 3) return Fail("bad --target-point");
  const rp::PerceptionConfig config;
  auto before = rp::LoadPcdFile(argv[2], config.limits);
  if (!before.ok()) return Fail(before.status().message());
  auto after = rp::LoadPcdFile(argv[3], config.limits);
  if (!after.ok()) return Fail(after.status().message());
  auto frame = rp::BuildFrame(*before, config);
  if (!frame.ok()) return Fail(frame.status().message());
  // The target: the supervoxel whose centroid is nearest to the given point.
  const Eigen::Vector3f point(x, y, z);
  const rp::Supervoxel* target = nullptr;
  for (const rp::Supervoxel& sv : frame->segmentation.supervoxels) {
    if (!target || (sv.centroid - point).norm() < (target->centroid - point).norm()) target = &sv;
  }
  if (!target) return Fail("the before cloud has no supervoxel");
  auto e = rp::DetectChange(*before, *after, *target, config.change);
  if (!e.ok()) return Fail(e.status().message());
  std::printf(
      "{\"moved\":%s,\"method\":\"%s\",\"target_supervoxel\":%u,"
      "\"target_centroid\":[%.4f,%.4f,%.4f],\"target_points\":%zu,\"supported_points\":%zu,"
      "\"vacated_points\":%zu,\"occluded_points\":%zu,\"difference_points\":%zu,"
      "\"after_statistical\":%zu,\"after_radius\":%zu,\"icp_ran\":%s,\"icp_converged\":%s,"
      "\"icp_fitness\":%.6g,\"change_ms\":%.1f}\n",
      e->moved ? "true" : "false", std::string(rp::ChangeMethodName(e->method)).c_str(), target->id,
      target->centroid.x(), target->centroid.y(), target->centroid.z(), e->target_points,
      e->supported_points, e->vacated_points, e->occluded_points, e->difference_points,
      e->after_statistical, e->after_radius, e->icp_ran ? "true" : "false",
      e->icp_converged ? "true" : "false", e->icp_ran ? e->icp_fitness : -1.0, e->elapsed_ms);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 2 && std::string(argv[1]) == "--change") return Change(argc, argv);
  if (argc < 2 || argv[1][0] == '-') {
    return Fail(
        "usage: relmap-perception <cloud.pcd | synthetic:WxH> [--voxel m] [--seed m] "
        "[--repeat n] [--png file] [--fpfh shared_voxels|exact_union|raw_points] "
        "[--colour corrected|paper2018] [--raw-spacing m] [--raw-normal-radius m] "
        "[--no-prevoxelise] [--threads n] "
        "[--fpfh-deviation] [--feature-stats] [--stride n]\n"
        "       relmap-perception --change before.pcd after.pcd --target-point x,y,z");
  }
  const std::string input = argv[1];
  rp::PerceptionConfig config;
  int repeat = 5;
  std::uint32_t stride = 1;
  std::string png;
  bool deviation = false;
  bool feature_stats = false;
  for (int i = 2; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--no-prevoxelise") {
      config.supervoxels.prevoxelise = false;
      continue;
    }
    if (flag == "--fpfh-deviation") {
      deviation = true;
      continue;
    }
    if (flag == "--feature-stats") {
      feature_stats = true;
      continue;
    }
    if (i + 1 >= argc) return Fail(flag + " needs a value");
    const std::string value = argv[++i];
    try {
      if (flag == "--voxel") {
        config.supervoxels.voxel_resolution = std::stof(value);
      } else if (flag == "--seed") {
        config.supervoxels.seed_resolution = std::stof(value);
      } else if (flag == "--repeat") {
        repeat = std::max(1, std::stoi(value));
      } else if (flag == "--stride") {
        stride = static_cast<std::uint32_t>(std::max(1, std::stoi(value)));
      } else if (flag == "--raw-spacing") {
        config.features.raw_point_spacing = std::stof(value);
      } else if (flag == "--raw-normal-radius") {
        config.features.raw_normal_radius = std::stof(value);
      } else if (flag == "--threads") {
        config.threads = std::stoi(value);
      } else if (flag == "--png") {
        png = value;
      } else if (flag == "--fpfh") {
        auto scheme = rp::ParseFpfhScheme(value);
        if (!scheme.ok()) return Fail(scheme.status().message());
        config.features.fpfh_scheme = *scheme;
      } else if (flag == "--colour") {
        auto colour = rp::ParseColourConversion(value);
        if (!colour.ok()) return Fail(colour.status().message());
        config.features.colour = *colour;
      } else {
        return Fail("unknown option " + flag);
      }
    } catch (const std::exception&) {
      return Fail("bad value '" + value + "' for " + flag);
    }
  }
  if (auto status = rp::Validate(config); !status.ok()) return Fail(status.message());

  std::string bytes;
  std::uint32_t width = 0, height = 0;
  const bool synthetic = input.rfind("synthetic:", 0) == 0;
  if (synthetic ? !SyntheticBytes(input, width, height, bytes) : !ReadFile(input, bytes)) {
    return Fail("cannot read '" + input + "'");
  }
  const bool packed = synthetic || stride > 1;
  if (!synthetic && stride > 1 && !DecimatedBytes(bytes, stride, width, height, bytes)) {
    return Fail("--stride needs an organized PCD cloud: '" + input + "'");
  }
  std::vector<double> decode, filter, supervoxels, normals, features, total;
  rp::Frame last;
  for (int r = 0; r < repeat; ++r) {
    const auto start = std::chrono::steady_clock::now();
    auto cloud = packed ? rp::DecodePacked(bytes, width, height, config.limits)
                        : rp::DecodePcd(bytes, config.limits);
    if (!cloud.ok()) return Fail(cloud.status().message());
    const double decode_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    auto frame = rp::BuildFrame(*cloud, config);
    if (!frame.ok()) return Fail(frame.status().message());
    decode.push_back(decode_ms);
    filter.push_back(frame->timings.filter_ms);
    supervoxels.push_back(frame->timings.supervoxels_ms);
    normals.push_back(frame->timings.normals_ms);
    features.push_back(frame->timings.features_ms);
    total.push_back(decode_ms + frame->timings.total_ms);
    last = std::move(frame).value();
  }
  if (!png.empty()) {
    if (auto status = rp::WriteSegmentationPng(last, png); !status.ok()) {
      return Fail(status.message());
    }
  }
  std::string extra;
  if (deviation) {
    // L1 distance per supervoxel between the shared and the exact FPFH (33 values, 3
    // blocks summing to 1 each, so at most 6), on this frame's segmentation.
    const Eigen::MatrixXd exact =
        rp::SupervoxelFpfhExactUnion(last.segmentation, config.features.fpfh_radius, 1);
    const Eigen::MatrixXd shared = rp::SupervoxelFpfhSharedVoxels(
        last.segmentation, config.features.fpfh_radius, config.threads);
    const Eigen::MatrixXd diff = (exact - shared).cwiseAbs();
    const Eigen::VectorXd l1 = diff.rowwise().sum();
    char buffer[160];
    std::snprintf(buffer, sizeof(buffer),
                  ",\"fpfh_l1_mean\":%.4f,\"fpfh_l1_max\":%.4f,\"fpfh_abs_max\":%.4f", l1.mean(),
                  l1.maxCoeff(), diff.maxCoeff());
    extra = buffer;
  }
  if (feature_stats) extra += FeatureStatsJson(last.features);
  // Voxels drive the cost of both stages more than points do (a far table gives one voxel
  // per pixel).
  std::size_t voxels = 0;
  for (const rp::Supervoxel& sv : last.segmentation.supervoxels) voxels += sv.voxels.size();
  std::printf(
      "{\"cloud\":\"%s\",\"stride\":%u,\"points\":%zu,\"valid_points\":%zu,\"voxels\":%zu,"
      "\"supervoxels\":%zu,\"non_finite_rows\":%zu,\"fpfh\":\"%s\",\"colour\":\"%s\","
      "\"raw_spacing\":%g,\"raw_normal_radius\":%g,\"prevoxelise\":%s,\"threads\":%"
      "d,\"repeat\":%d,"
      "\"median_ms\":{\"decode\":%.1f,\"filter\":%.1f,\"supervoxels\":%.1f,\"normals\":%.1f,"
      "\"features\":%.1f,\"total\":%.1f}%s}\n",
      input.c_str(), stride, last.cloud.size(), last.cloud.valid_points(), voxels, last.size(),
      last.features.non_finite_rows,
      std::string(rp::FpfhSchemeName(config.features.fpfh_scheme)).c_str(),
      std::string(rp::ColourConversionName(config.features.colour)).c_str(),
      static_cast<double>(config.features.raw_point_spacing),
      static_cast<double>(config.features.raw_normal_radius),
      config.supervoxels.prevoxelise ? "true" : "false", config.threads, repeat, Median(decode),
      Median(filter), Median(supervoxels), Median(normals), Median(features), Median(total),
      extra.c_str());
  return 0;
}
