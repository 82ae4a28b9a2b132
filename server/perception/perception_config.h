// Configuration of the perception layer: decoding limits, VCCS supervoxels (docs/method.md §1),
// features (§2) and change detection (§5), with the authors' values as defaults.
#pragma once

#include <string_view>

#include "common/status.h"

namespace relmap::perception {

// The largest |coordinate| a decoded cloud may have, in metres (DecodeLimits).
inline constexpr float kMaxAbsCoordinate = 100.0f;

// The deepest grid relmap lets a cloud make: GridCellKey packs 21 bits per axis, and
// PCL's octrees (VCCS's adjacency octree, the change detector's) get one level deeper per
// halving of the cell, so a resolution is refused up front when a cloud spanning
// [-kMaxAbsCoordinate, kMaxAbsCoordinate] would need more levels than this.
inline constexpr int kMaxGridDepth = 21;

// The levels of PCL's octree over a cube of side `extent` with cells of side `resolution`:
// ceil(log2(extent / resolution)), at least 1 (OctreePointCloud::getKeyBitSize).
constexpr int OctreeDepth(double extent, double resolution) {
  int depth = 1;
  while (static_cast<double>(1LL << depth) * resolution < extent && depth < 62) ++depth;
  return depth;
}

// The finest cell that keeps the depth within kMaxGridDepth over the allowed coordinates:
// 2 * 100 m / 2^21 = 9.54e-5 m. Every resolution's lower bound below is at least this.
inline constexpr double kFinestGridCell =
    2.0 * kMaxAbsCoordinate / static_cast<double>(1LL << kMaxGridDepth);

// Bounds checked before any decoded byte reaches PCL (its PCD readers have had heap
// overflows on malformed files).
struct DecodeLimits {
  // 4x a 640x480 frame: enough for any depth camera we serve, small enough to bound memory.
  long long max_points = 1280LL * 960LL;
  long long max_bytes = 256LL << 20;
  // Points farther than this from the camera are rejected: PCL's octrees grow one level per
  // doubling of the extent, and absurd coordinates (1e30) make them unusable.
  float max_abs_coordinate = kMaxAbsCoordinate;
};

// Optional workspace crop, in the camera frame (§1: the authors' workbench box was
// x∈[−0.38, 0.20], y∈[−0.10, 0.35], z∈[0.85, 2.0]; relmap's default is no crop).
struct CropBox {
  bool enabled = false;
  float min_x = -0.38f, max_x = 0.20f;
  float min_y = -0.10f, max_y = 0.35f;
  float min_z = 0.85f, max_z = 2.0f;
};

// §1: PCL SupervoxelClustering (VCCS) with the authors' values.
struct SupervoxelConfig {
  float voxel_resolution = 0.008f;
  float seed_resolution = 0.05f;
  float colour_importance = 0.2f;
  float spatial_importance = 0.4f;
  float normal_importance = 0.4f;
  bool single_camera_transform = false;
  // Supervoxels with fewer voxels are dropped, and vanish from the adjacency (§1).
  int min_voxels = 6;
  CropBox crop;
  // Speed-up (not in the paper): average the raw points on a voxel_resolution grid before
  // VCCS, which voxelises at that resolution anyway. VCCS's grid is anchored at the first
  // point, ours at the origin, so voxels shift slightly; off = the exact §1 pipeline.
  bool prevoxelise = true;
};

enum class ColourConversion {
  kCorrected,  // true CIELab: sRGB gamma linearisation, D65 (§2 `corrected`)
  kPaper2018,  // the authors' code: no linearisation, 0-255 values into the XYZ matrix
};

enum class FpfhScheme {
  // §2 literally: per supervoxel, PCL FPFH at every voxel of the supervoxel ∪ its
  // neighbours, with that union as search surface. Every voxel is computed ~7 times.
  kExactUnion,
  // One SPFH and one FPFH per voxel over the whole voxel cloud (one radius search), then the
  // union average. Differs from kExactUnion only near the union's border; the deviation is
  // measured by the tests and benchmarks.
  kSharedVoxels,
  // The paper's words (§2 of the paper: "on the raw points"): per supervoxel, FPFH at the raw
  // input points of the supervoxel ∪ its neighbours, that union as search surface, normals
  // estimated from the raw points. A 5 cm ball holds thousands of raw points, so the points
  // are first thinned to one per raw_point_spacing cell (docs/features.md).
  kRawPoints,
};

// The accepted supervoxel resolutions, in metres (Validate).
inline constexpr float kMinVoxelResolution = 0.001f;
inline constexpr float kMaxVoxelResolution = 1.0f;
inline constexpr float kMaxSeedResolution = 10.0f;

// The accepted FPFH radii, in metres (Validate).
inline constexpr float kMinFpfhRadius = 0.005f;
inline constexpr float kMaxFpfhRadius = 0.5f;

// The accepted octree cells of the change detector (kPaper2018), in metres (Validate).
inline constexpr double kMinOctreeResolution = 1e-3;
inline constexpr double kMaxOctreeResolution = 1.0;

// The change detector's smallest motion that counts (kVisibility), in metres (Validate), and
// the widest pixel window searched for it: +-24 px covers 1 cm at 0.24 m on a 640x480 Kinect
// (fx 580) and bounds a point's lookups at 49 x 49.
inline constexpr double kMaxMinMotion = 0.1;
inline constexpr int kMaxMotionWindow = 24;

// 1 mm cells over 200 m make an 18-level octree; its leaves are at most the cloud's points
// (DecodeLimits::max_points), its inner nodes at most 18 per leaf.
static_assert(kMinVoxelResolution >= kFinestGridCell);
static_assert(kMinOctreeResolution >= kFinestGridCell);
static_assert(OctreeDepth(2.0 * kMaxAbsCoordinate, kMinOctreeResolution) <= kMaxGridDepth);
static_assert(OctreeDepth(2.0 * kMaxAbsCoordinate, kFinestGridCell) == kMaxGridDepth);

// §2: 15 colour-histogram values then 33 FPFH values per supervoxel.
struct FeatureConfig {
  ColourConversion colour = ColourConversion::kCorrected;
  FpfhScheme fpfh_scheme = FpfhScheme::kSharedVoxels;
  float fpfh_radius = 0.05f;
  // kRawPoints only: at most one raw point (the first in input order, not an average) per
  // cell of this size in metres; 0 keeps every raw point (tens of seconds per frame).
  float raw_point_spacing = 0.004f;
  // kRawPoints only: the normal of each raw point is the PCA normal of the thinned raw points
  // within this radius in metres; 0 gives it the VCCS normal of its voxel instead. VCCS
  // normals are constant over a voxel, which keeps the angle blocks as peaked as the voxel
  // schemes'; 1 cm raw normals carry the sensor noise the paper's FPFH saw (docs/features.md).
  float raw_normal_radius = 0.01f;
  // Values below this are set to 0 (the authors' code from Feb. 2018 on).
  double zero_below = 1e-3;
};

// The depth noise of the camera, as a structured-light RGB-D sensor's (Kinect v1, Xtion):
// axial standard deviation sigma(z) = base + quadratic * (z - reference)^2 (Nguyen, Izadi &
// Lovell 2012, "Modeling Kinect Sensor Noise for Improved 3D Reconstruction and Tracking",
// eq. 6, fitted for 10-60 degree incidence), and a depth step of quantisation * z^2 from the
// 1/8-pixel disparity (Khoshelham & Elberink 2012, Sensors 12:1437: step = z^2 / (8 f b) with
// f = 580 px and b = 7.5 cm). Another camera sets its own figures.
struct DepthNoiseModel {
  double sigma_base = 0.0012;                         // m
  double sigma_quadratic = 0.0019;                    // 1/m
  double reference_depth = 0.4;                       // m
  double quantisation = 1.0 / (8.0 * 580.0 * 0.075);  // 1/m, ~0.0029

  double Sigma(double z) const {
    return sigma_base + sigma_quadratic * (z - reference_depth) * (z - reference_depth);
  }
  double Step(double z) const { return quantisation * z * z; }
};

// How a push is labelled (§5 and docs/method.md §5.1).
enum class ChangeMethod {
  // relmap's: each point of the target is tested against the after frame along its own
  // pixel's ray, with the camera's noise model: still there, seen through (vacated) or
  // hidden by something nearer (occluded). Moved iff enough of it is seen through.
  kVisibility,
  // The authors': octree difference, outlier removal, ICP of the target onto the difference.
  kPaper2018,
};

struct ChangeDetectorConfig {
  ChangeMethod method = ChangeMethod::kVisibility;

  // kVisibility. A target point is still there when an after-point lies within
  // tolerance_sigmas * sqrt(2) * sigma(z) + step(z) of it (both frames are noisy, and each
  // is quantised) in a window of +-search_window pixels around its own (lateral noise is
  // 0.8 px at 640x480 and incidences below 60 degrees, Nguyen et al. 2012, fig. 8: 2 px is
  // 2.5 sigma; a smaller image has less).
  DepthNoiseModel noise;
  double tolerance_sigmas = 3.0;
  int search_window = 2;  // pixels
  // A point is still there only if it also looks the same: every channel within this many
  // 8-bit levels once the frame's exposure gain is taken out (0: geometry only, the
  // default). A surface that slid in its own plane (a brick's top) is only seen by its
  // texture (a wood grain's contrast is 40-60 levels), but between the real frames of
  // kinect_static_seq_* 25 of 45 points of one supervoxel change by more than 64 levels:
  // off until it holds on real data.
  double colour_tolerance = 0;
  // The target moved iff it or its object (change_object.h) did, each judged alike: at least
  // this share of its points that the after frame shows still there or vacated was seen
  // through (occluded points, behind something nearer, say neither), at least
  // min_vacated_points of them, and the after frame shows at least half of it (occluded points
  // included). On the simulated setups with an ideal camera, pushes that moved their target
  // left 0.44-1.0 of it vacated and pushes that did not 0-0.03 (docs/results.md §C).
  double min_vacated_fraction = 0.2;
  int min_vacated_points = 10;
  // Two adjacent supervoxels lie on one object when their connection is convex or their
  // normals are less than this apart (change_object.h; LCCP's concavity tolerance, Stein et
  // al. 2014, whose default is 10 degrees).
  double object_smooth_angle_deg = 10.0;
  // With a moved target, the session also learns as moveable the object's supervoxels the
  // detector saw move (ChangeEvidence::moved_supervoxels, docs/method.md §4.5).
  bool learn_moved_object = true;
  // The smallest motion that counts as a move, in metres (0: any the camera can see). A
  // move then also needs min_vacated_points vacated points with no after-point within this
  // distance, searched over as many pixels as it spans at the point's depth (at most
  // kMaxMotionWindow, each way): a body nudged by 5 mm while its neighbour was pushed away
  // did not move for a client whose "moved" means more than 1 cm (relmap-sim tells the
  // server its scene's threshold). The vacated share is still judged by the noise alone,
  // so that a true move keeps the evidence of every point it left.
  double min_motion = 0;
  // Register the after frame onto the before frame first (camera_motion.h): ICP of
  // motion_samples after-points, pairs farther apart than motion_max_distance left out (what
  // the push moved). 5 cm covers the 1.2 degrees and 1.3 cm of kinect_static_seq_* at 2 m.
  bool compensate_camera_motion = true;
  int motion_samples = 5000;
  float motion_max_distance = 0.05f;  // m

  // kPaper2018.
  double octree_resolution = 0.01;
  // An emptied cell counts only if it held at least this many before-points (0: the
  // authors' setting).
  int min_points_per_cell = 0;
  // Not in the paper: a difference point is kept only if no after-point lies within
  // max(octree_resolution, depth_noise * z²) of it (tested on a grid of octree_resolution
  // cells). Between two frames of kinect_static_seq_* the depth of a static scene shifts by
  // ~0.4 cm at 0.6 m and ~2 cm at 1.5 m (quantisation and drift), which empties tens of
  // thousands of cells; ICP then fits targets onto that noise. 0 = the authors' pipeline
  // (no such check).
  double depth_noise = 0.016;  // 1/m
  int sor_mean_k = 10;
  double sor_stddev_mul = 0.001;
  double ror_radius = 0.01;
  int ror_min_neighbours = 20;
  int icp_max_iterations = 10;
  double icp_max_correspondence = 0.005;
  double max_fitness = 1e-4;  // m², mean squared nearest distance
};

struct PerceptionConfig {
  DecodeLimits limits;
  SupervoxelConfig supervoxels;
  FeatureConfig features;
  ChangeDetectorConfig change;
  // Worker threads for the parallel stages (features, FPFH). 0 = OpenMP's default.
  int threads = 2;
};

// Checks every range in one place; the message names the offending field.
Status Validate(const PerceptionConfig& config);

std::string_view ColourConversionName(ColourConversion conversion);
StatusOr<ColourConversion> ParseColourConversion(std::string_view name);
std::string_view FpfhSchemeName(FpfhScheme scheme);
std::string_view ChangeMethodName(ChangeMethod method);
StatusOr<ChangeMethod> ParseChangeMethod(std::string_view name);
StatusOr<FpfhScheme> ParseFpfhScheme(std::string_view name);

}  // namespace relmap::perception
