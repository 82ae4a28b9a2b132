// The 48-d feature of §2: colour conversions, histogram invariants, FPFH against PCL, and
// the deviation of the shared FPFH scheme from the exact one, the raw-point scheme.
#include "perception/features.h"

#include <gtest/gtest.h>
#include <pcl/features/fpfh.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>

#include <map>
#include <memory>
#include <string>

#include "perception/change_object.h"
#include "perception/colour_histogram.h"
#include "perception/fpfh.h"
#include "perception/frame.h"
#include "perception/synthetic_tabletop.h"
#include "test_data.h"

namespace relmap::perception {
namespace {

TEST(RgbToLab, CorrectedIsTrueCielab) {
  // sRGB red is L* 53.24, a* 80.09, b* 67.20 in every CIELab table.
  const Eigen::Vector3d red = RgbToLab({255, 0, 0}, ColourConversion::kCorrected);
  EXPECT_NEAR(red[0], 53.24, 0.1);
  EXPECT_NEAR(red[1], 80.09, 0.2);
  EXPECT_NEAR(red[2], 67.20, 0.2);
  const Eigen::Vector3d white = RgbToLab({255, 255, 255}, ColourConversion::kCorrected);
  EXPECT_NEAR(white[0], 100.0, 0.05);
  EXPECT_NEAR(white[1], 0.0, 0.05);
  EXPECT_NEAR(white[2], 0.0, 0.05);
}

TEST(RgbToLab, Paper2018SaturatesLightness) {
  // Mid grey without linearisation: Y = (0.2126 + 0.7152 + 0.0722) * 128 / 100 = 1.28,
  // f = 1.28^(1/3) = 1.0858, L = 116 * 1.0858 - 16 = 109.95, clipped to 100.
  EXPECT_DOUBLE_EQ(RgbToLab({128, 128, 128}, ColourConversion::kPaper2018)[0], 100.0);
  EXPECT_LT(RgbToLab({128, 128, 128}, ColourConversion::kCorrected)[0], 60.0);
}

TEST(ColourHistogram, BinsLabOverTheVoxelColours) {
  // White: L/100 = 1 goes to the last L bin; a = b = 0 map to (0 + 1) / 2 * 5 = 2.5 -> bin 2.
  // Black: L = 0 -> bin 0; a = b = 0 -> bin 2. Each count is divided by the 2 colours.
  const auto h = ColourHistogram({{255, 255, 255}, {0, 0, 0}}, ColourConversion::kCorrected);
  Eigen::Matrix<double, kColourDims, 1> expected;
  expected << 0.5, 0, 0, 0, 0.5, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0;
  EXPECT_TRUE(h.isApprox(expected)) << h.transpose();
}

void ExpectInvariants(const FeatureMatrix& f) {
  ASSERT_EQ(f.values.cols(), kFeatureDims);
  EXPECT_EQ(f.non_finite_rows, 0u);
  for (Eigen::Index r = 0; r < f.values.rows(); ++r) {
    EXPECT_GE(f.values.row(r).minCoeff(), 0.0) << r;
    EXPECT_LE(f.values.row(r).maxCoeff(), 1.0) << r;
    for (int block = 0; block < 3; ++block) {  // colour histograms: exact counts / n
      EXPECT_NEAR(f.values.row(r)
                      .segment(static_cast<Eigen::Index>(block) * kColourBins, kColourBins)
                      .sum(),
                  1.0, 1e-9);
    }
    for (int block = 0; block < 3; ++block) {  // FPFH: 1 less what zeroing < 1e-3 removed
      const double sum = f.values.row(r).segment(kColourDims + block * kFpfhBins, kFpfhBins).sum();
      EXPECT_LE(sum, 1.0 + 1e-5) << r;  // voxel FPFH are floats
      EXPECT_GE(sum, 1.0 - kFpfhBins * 1e-3) << r;
    }
  }
}

TEST(Features, SubHistogramsSumToOneAndValuesLieInTheUnitInterval) {
  const SyntheticTabletop scene = testing::SmallSyntheticScene();
  for (FpfhScheme scheme :
       {FpfhScheme::kSharedVoxels, FpfhScheme::kExactUnion, FpfhScheme::kRawPoints}) {
    SCOPED_TRACE(std::string(FpfhSchemeName(scheme)));
    PerceptionConfig config;
    config.features.fpfh_scheme = scheme;
    StatusOr<Frame> frame = BuildFrame(scene.cloud, config);
    ASSERT_TRUE(frame.ok()) << frame.status().message();
    ASSERT_EQ(frame->features.values.rows(), static_cast<Eigen::Index>(frame->size()));
    ExpectInvariants(frame->features);
  }
}

TEST(Features, InvariantsHoldOnARealCloud) {
  RELMAP_LOAD_REAL_CLOUD(cloud, "milk_cartoon_all_small_clorox.pcd");
  StatusOr<Frame> frame = BuildFrame(cloud, PerceptionConfig{});
  ASSERT_TRUE(frame.ok()) << frame.status().message();
  ExpectInvariants(frame->features);
}

TEST(Features, RawPointFpfhIsFiniteOnARealCloud) {
  RELMAP_LOAD_REAL_CLOUD(cloud, "table_scene_mug_stereo_textured.pcd");
  PerceptionConfig config;
  config.features.fpfh_scheme = FpfhScheme::kRawPoints;
  StatusOr<Frame> frame = BuildFrame(cloud, config);
  ASSERT_TRUE(frame.ok()) << frame.status().message();
  ExpectInvariants(frame->features);
}

TEST(Features, ColourConversionChangesOnlyTheColourBlock) {
  const SyntheticTabletop scene = testing::SmallSyntheticScene();
  StatusOr<Segmentation> seg = ExtractSupervoxels(scene.cloud, SupervoxelConfig{});
  ASSERT_TRUE(seg.ok());
  FeatureConfig corrected, paper;
  paper.colour = ColourConversion::kPaper2018;
  const FeatureMatrix a = ComputeFeatures(scene.cloud, *seg, corrected, 2);
  const FeatureMatrix b = ComputeFeatures(scene.cloud, *seg, paper, 2);
  EXPECT_TRUE(a.values.rightCols<kFpfhDims>() == b.values.rightCols<kFpfhDims>());
  EXPECT_FALSE(a.values.leftCols<kColourDims>() == b.values.leftCols<kColourDims>());
}

// PointFpfh reimplements FPFHEstimation (a grid radius search, the pair kernel of
// pair_features.h); it must give PCL's histograms.
TEST(PointFpfh, MatchesPclFpfhEstimation) {
  std::vector<Eigen::Vector3f> positions, normals;
  testing::SmallSceneVoxels(positions, normals);
  ASSERT_FALSE(positions.empty());
  const Eigen::MatrixXf ours = PointFpfh(positions, normals, 0.05f, 2);

  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  pcl::PointCloud<pcl::Normal>::Ptr cloud_normals(new pcl::PointCloud<pcl::Normal>);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    cloud->push_back({positions[i].x(), positions[i].y(), positions[i].z()});
    pcl::Normal n;
    n.getNormalVector3fMap() = normals[i];
    cloud_normals->push_back(n);
  }
  pcl::FPFHEstimation<pcl::PointXYZ, pcl::Normal, pcl::FPFHSignature33> estimation;
  estimation.setInputCloud(cloud);
  estimation.setInputNormals(cloud_normals);
  estimation.setSearchMethod(std::make_shared<pcl::search::KdTree<pcl::PointXYZ>>());
  estimation.setRadiusSearch(0.05);
  pcl::PointCloud<pcl::FPFHSignature33> theirs;
  estimation.compute(theirs);
  ASSERT_EQ(theirs.size(), positions.size());
  float worst = 0;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    for (int b = 0; b < kFpfhDims; ++b) {
      worst = std::max(worst, std::fabs(ours(static_cast<Eigen::Index>(i), b) -
                                        theirs[i].histogram[b] / 100.0f));
    }
  }
  ::testing::Test::RecordProperty("worst_abs", std::to_string(worst));
  EXPECT_LT(worst, 1e-5f);  // same pairs and bins as PCL: float summation order only
}

// The shared scheme differs from §2's literal one near the border of each union: measure.
TEST(SupervoxelFpfh, SharedSchemeStaysCloseToTheExactOne) {
  const SyntheticTabletop scene = testing::SmallSyntheticScene();
  StatusOr<Segmentation> seg = ExtractSupervoxels(scene.cloud, SupervoxelConfig{});
  ASSERT_TRUE(seg.ok());
  const Eigen::MatrixXd exact = SupervoxelFpfhExactUnion(*seg, 0.05f, 2);
  const Eigen::MatrixXd shared = SupervoxelFpfhSharedVoxels(*seg, 0.05f, 2);
  // L1 distance per supervoxel over the 33 values (3 blocks of sum 1: at most 6).
  const Eigen::VectorXd l1 = (exact - shared).cwiseAbs().rowwise().sum();
  ::testing::Test::RecordProperty("mean_l1", std::to_string(l1.mean()));
  ::testing::Test::RecordProperty("max_l1", std::to_string(l1.maxCoeff()));
  EXPECT_LT(l1.mean(), 0.25);
}

// A tilted plane z = 1 + 0.1 x of 4 mm spaced points, 24 cm square, seen from the origin.
Cloud TiltedPlane() {
  std::vector<CloudPoint> points;
  constexpr int kSide = 60;
  for (int v = 0; v < kSide; ++v) {
    for (int u = 0; u < kSide; ++u) {
      const float x = -0.12f + 0.004f * static_cast<float>(u);
      const float y = -0.12f + 0.004f * static_cast<float>(v);
      points.push_back({x, y, 1.0f + 0.1f * x, 128, 128, 128, 255});
    }
  }
  StatusOr<Cloud> cloud = MakeCloud(kSide, kSide, std::move(points));
  EXPECT_TRUE(cloud.ok()) << cloud.status().message();
  return cloud.ok() ? *cloud : Cloud();
}

// The raw scheme is PointFpfh at the raw points of each union, that union as search surface,
// averaged. On a plane every normal is the plane's, so every pair lies in the middle bin of
// each block: f1 = atan2(0, 1) = 0 -> 11 * (0 + π) / 2π = 5.5, f2 = f3 = 0 -> 11 * 0.5 = 5.5.
TEST(SupervoxelFpfh, RawPointsOnAPlaneAreTheUnionsPointFpfh) {
  const Cloud cloud = TiltedPlane();
  StatusOr<Segmentation> seg = ExtractSupervoxels(cloud, SupervoxelConfig{});
  ASSERT_TRUE(seg.ok()) << seg.status().message();
  ASSERT_GT(seg->supervoxels.size(), 4u);
  FeatureConfig config;
  config.raw_point_spacing = 0.0f;  // every raw point, as PointFpfh below gets them
  const Eigen::MatrixXd raw = SupervoxelFpfhRawPoints(cloud, *seg, config, 2);
  const Eigen::Vector3f plane_normal = Eigen::Vector3f(0.1f, 0.0f, -1.0f).normalized();
  Eigen::RowVectorXd middle = Eigen::RowVectorXd::Zero(kFpfhDims);
  middle(5) = middle(kFpfhBins + 5) = middle(2 * kFpfhBins + 5) = 1.0;
  for (const Supervoxel& sv : seg->supervoxels) {
    std::vector<Eigen::Vector3f> positions;
    const auto add = [&](const Supervoxel& member) {
      for (std::int32_t i : member.point_indices) {
        const CloudPoint p = cloud.point(static_cast<std::size_t>(i));
        positions.emplace_back(p.x, p.y, p.z);
      }
    };
    add(sv);
    for (std::uint32_t nb : sv.neighbours) add(seg->supervoxels[nb]);
    const std::vector<Eigen::Vector3f> normals(positions.size(), plane_normal);
    const Eigen::RowVectorXd expected =
        PointFpfh(positions, normals, config.fpfh_radius, 2).cast<double>().colwise().mean();
    EXPECT_LT((raw.row(sv.id) - expected).cwiseAbs().maxCoeff(), 1e-6) << sv.id;
    EXPECT_LT((raw.row(sv.id) - middle).cwiseAbs().maxCoeff(), 1e-6) << sv.id;
  }
}

TEST(FeatureConfig, RadiiOutsideTheirRangesAreInvalid) {
  PerceptionConfig config;
  config.features.fpfh_radius = 0.001f;
  EXPECT_FALSE(Validate(config).ok());
  config.features.fpfh_radius = 0.6f;
  EXPECT_FALSE(Validate(config).ok());
  config.features.fpfh_radius = 0.05f;
  config.features.raw_point_spacing = 0.05f;  // one point per ball: no histogram
  EXPECT_FALSE(Validate(config).ok());
  config.features.raw_point_spacing = 0.0f;
  EXPECT_TRUE(Validate(config).ok());
}

// BuildFrame gives each supervoxel its object (ObjectLabels with the change detector's
// angle): the mug scene's table is one object of many supervoxels, and not every
// supervoxel is on it.
TEST(Frame, GivesEverySupervoxelTheObjectOfChangeObject) {
  RELMAP_LOAD_REAL_CLOUD(cloud, "table_scene_mug_stereo_textured.pcd");
  const PerceptionConfig config;
  StatusOr<Frame> frame = BuildFrame(cloud, config);
  ASSERT_TRUE(frame.ok()) << frame.status().message();
  ASSERT_EQ(frame->objects.size(), frame->size());
  EXPECT_EQ(frame->objects,
            ObjectLabels(frame->segmentation.supervoxels, config.change.object_smooth_angle_deg));
  std::map<std::uint32_t, std::size_t> sizes;
  for (const std::uint32_t object : frame->objects) ++sizes[object];
  EXPECT_GT(sizes.size(), 1u);
  EXPECT_LT(sizes.size(), frame->size());
}

}  // namespace
}  // namespace relmap::perception
