// Validation and names of the perception configuration.
#include "perception/perception_config.h"

#include <cmath>
#include <string>

namespace relmap::perception {
namespace {

bool Positive(double v) { return std::isfinite(v) && v > 0.0; }
bool NonNegative(double v) { return std::isfinite(v) && v >= 0.0; }

Status Field(const std::string& name, const std::string& requirement) {
  return InvalidArgumentError("perception config: " + name + " must be " + requirement);
}

Status ValidateCrop(const CropBox& c) {
  if (!c.enabled) return OkStatus();
  const float all[] = {c.min_x, c.max_x, c.min_y, c.max_y, c.min_z, c.max_z};
  for (float v : all) {
    if (!std::isfinite(v)) return Field("crop box bounds", "finite");
  }
  if (!(c.min_x < c.max_x && c.min_y < c.max_y && c.min_z < c.max_z)) {
    return Field("crop box", "non-empty (min < max on every axis)");
  }
  return OkStatus();
}

}  // namespace

Status Validate(const PerceptionConfig& config) {
  const DecodeLimits& l = config.limits;
  if (l.max_points <= 0) return Field("limits.max_points", "> 0");
  if (l.max_bytes <= 0) return Field("limits.max_bytes", "> 0");
  if (!Positive(l.max_abs_coordinate)) return Field("limits.max_abs_coordinate", "> 0");

  const SupervoxelConfig& s = config.supervoxels;
  // PCL's octrees assert (and abort the process) when a cloud's extent over the resolution
  // needs more key bits than they have (1e-9 m did); finer than 1 mm is below any depth
  // camera's noise, coarser than 1 m leaves nothing of a table-top object.
  if (!(s.voxel_resolution >= kMinVoxelResolution && s.voxel_resolution <= kMaxVoxelResolution)) {
    return Field("supervoxels.voxel_resolution", "in [0.001, 1] m");
  }
  if (!(s.seed_resolution >= s.voxel_resolution && s.seed_resolution <= kMaxSeedResolution)) {
    return Field("supervoxels.seed_resolution", "in [voxel_resolution, 10] m");
  }
  if (!NonNegative(s.colour_importance)) return Field("supervoxels.colour_importance", ">= 0");
  if (!NonNegative(s.spatial_importance)) return Field("supervoxels.spatial_importance", ">= 0");
  if (!NonNegative(s.normal_importance)) return Field("supervoxels.normal_importance", ">= 0");
  if (s.min_voxels < 1) return Field("supervoxels.min_voxels", ">= 1");
  if (Status st = ValidateCrop(s.crop); !st.ok()) return st;

  const FeatureConfig& f = config.features;
  // Below 5 mm a ball meets too few voxels for a histogram (8 mm voxels); beyond 0.5 m one
  // radius search spans the whole workbench and a frame takes minutes.
  if (!(f.fpfh_radius >= kMinFpfhRadius && f.fpfh_radius <= kMaxFpfhRadius)) {
    return Field("features.fpfh_radius", "in [0.005, 0.5] m");
  }
  // GridCellKey's 21 bits per axis hold ±100 m at 0.1 mm cells.
  if (!(f.raw_point_spacing == 0.0f ||
        (f.raw_point_spacing >= 1e-4f && f.raw_point_spacing < f.fpfh_radius))) {
    return Field("features.raw_point_spacing", "0 or in [0.0001, fpfh_radius) m");
  }
  if (!NonNegative(f.raw_normal_radius) || f.raw_normal_radius > f.fpfh_radius) {
    return Field("features.raw_normal_radius", "in [0, fpfh_radius] m");
  }
  if (!NonNegative(f.zero_below) || f.zero_below >= 1.0) {
    return Field("features.zero_below", "in [0, 1)");
  }

  const ChangeDetectorConfig& c = config.change;
  // A noise model of metres and 1/m: anything beyond a metre of noise is not a camera.
  const DepthNoiseModel& n = c.noise;
  if (!NonNegative(n.sigma_base) || n.sigma_base > 1.0) {
    return Field("change.noise.sigma_base", "in [0, 1] m");
  }
  if (!NonNegative(n.sigma_quadratic) || n.sigma_quadratic > 1.0) {
    return Field("change.noise.sigma_quadratic", "in [0, 1] 1/m");
  }
  if (!NonNegative(n.reference_depth) || n.reference_depth > 10.0) {
    return Field("change.noise.reference_depth", "in [0, 10] m");
  }
  if (!NonNegative(n.quantisation) || n.quantisation > 1.0) {
    return Field("change.noise.quantisation", "in [0, 1] 1/m");
  }
  if (!Positive(c.tolerance_sigmas) || c.tolerance_sigmas > 10.0) {
    return Field("change.tolerance_sigmas", "in (0, 10]");
  }
  if (c.search_window < 0 || c.search_window > 8) return Field("change.search_window", "in [0, 8]");
  if (!NonNegative(c.colour_tolerance) || c.colour_tolerance > 255) {
    return Field("change.colour_tolerance", "in [0, 255]");
  }
  if (!Positive(c.min_vacated_fraction) || c.min_vacated_fraction > 1.0) {
    return Field("change.min_vacated_fraction", "in (0, 1]");
  }
  if (c.min_vacated_points < 1) return Field("change.min_vacated_points", ">= 1");
  if (c.object_smooth_angle_deg < 0 || c.object_smooth_angle_deg > 90.0) {
    return Field("change.object_smooth_angle_deg", "in [0, 90]");
  }
  if (!NonNegative(c.min_motion) || c.min_motion > kMaxMinMotion) {
    return Field("change.min_motion", "in [0, 0.1] m");
  }
  // The registration's cost grows with its samples (and 4x as many on the other side).
  if (c.motion_samples < 100 || c.motion_samples > 200000) {
    return Field("change.motion_samples", "in [100, 200000]");
  }
  if (!(c.motion_max_distance > 0.0f && c.motion_max_distance <= 1.0f)) {
    return Field("change.motion_max_distance", "in (0, 1] m");
  }
  // Finer cells than 1 mm are below any depth camera's noise and grow the octree without
  // bound (1e-9 m exhausted memory).
  if (!(c.octree_resolution >= kMinOctreeResolution &&
        c.octree_resolution <= kMaxOctreeResolution)) {
    return Field("change.octree_resolution", "in [0.001, 1] m");
  }
  if (c.min_points_per_cell < 0) return Field("change.min_points_per_cell", ">= 0");
  if (!NonNegative(c.depth_noise)) return Field("change.depth_noise", ">= 0");
  if (c.sor_mean_k < 1) return Field("change.sor_mean_k", ">= 1");
  if (!NonNegative(c.sor_stddev_mul)) return Field("change.sor_stddev_mul", ">= 0");
  if (!Positive(c.ror_radius)) return Field("change.ror_radius", "> 0");
  if (c.ror_min_neighbours < 0) return Field("change.ror_min_neighbours", ">= 0");
  if (c.icp_max_iterations < 1) return Field("change.icp_max_iterations", ">= 1");
  if (!Positive(c.icp_max_correspondence)) return Field("change.icp_max_correspondence", "> 0");
  if (!Positive(c.max_fitness)) return Field("change.max_fitness", "> 0");

  if (config.threads < 0 || config.threads > 256) return Field("threads", "in [0, 256]");
  return OkStatus();
}

std::string_view ColourConversionName(ColourConversion conversion) {
  return conversion == ColourConversion::kPaper2018 ? "paper2018" : "corrected";
}

StatusOr<ColourConversion> ParseColourConversion(std::string_view name) {
  if (name == "corrected") return ColourConversion::kCorrected;
  if (name == "paper2018") return ColourConversion::kPaper2018;
  return InvalidArgumentError("unknown colour conversion '" + std::string(name) +
                              "' (expected corrected or paper2018)");
}

std::string_view FpfhSchemeName(FpfhScheme scheme) {
  switch (scheme) {
    case FpfhScheme::kExactUnion:
      return "exact_union";
    case FpfhScheme::kRawPoints:
      return "raw_points";
    case FpfhScheme::kSharedVoxels:
      break;
  }
  return "shared_voxels";
}

StatusOr<FpfhScheme> ParseFpfhScheme(std::string_view name) {
  // "exact" and "shared": the names before raw_points existed, still in scripts and READMEs.
  if (name == "exact_union" || name == "exact") return FpfhScheme::kExactUnion;
  if (name == "shared_voxels" || name == "shared") return FpfhScheme::kSharedVoxels;
  if (name == "raw_points") return FpfhScheme::kRawPoints;
  return InvalidArgumentError("unknown FPFH scheme '" + std::string(name) +
                              "' (expected shared_voxels, exact_union or raw_points)");
}

std::string_view ChangeMethodName(ChangeMethod method) {
  return method == ChangeMethod::kPaper2018 ? "paper2018" : "visibility";
}

StatusOr<ChangeMethod> ParseChangeMethod(std::string_view name) {
  if (name == "visibility") return ChangeMethod::kVisibility;
  if (name == "paper2018") return ChangeMethod::kPaper2018;
  return InvalidArgumentError("unknown change detection method '" + std::string(name) +
                              "' (expected visibility or paper2018)");
}

}  // namespace relmap::perception
