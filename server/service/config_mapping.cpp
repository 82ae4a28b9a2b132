// Field-by-field mapping; unset optional fields keep the paper's defaults.
#include "service/config_mapping.h"

#include <string>

#include "exploration/exploration_spec.h"

namespace relmap::service {
namespace {

// proto3 enums are open: a client may send any number, which must not become a default.
StatusOr<perception::FeatureConfig> FeaturesFromProto(const v1::FeatureConfig& in) {
  perception::FeatureConfig out;
  switch (in.colour()) {
    case v1::COLOUR_VARIANT_UNSPECIFIED:
    case v1::COLOUR_VARIANT_CORRECTED:
      out.colour = perception::ColourConversion::kCorrected;
      break;
    case v1::COLOUR_VARIANT_PAPER2018:
      out.colour = perception::ColourConversion::kPaper2018;
      break;
    default:
      return InvalidArgumentError("config.features.colour: unknown value " +
                                  std::to_string(in.colour()));
  }
  switch (in.fpfh_scheme()) {
    case v1::FPFH_SCHEME_UNSPECIFIED:
    case v1::FPFH_SCHEME_SHARED_VOXELS:
      out.fpfh_scheme = perception::FpfhScheme::kSharedVoxels;
      break;
    case v1::FPFH_SCHEME_EXACT_UNION:
      out.fpfh_scheme = perception::FpfhScheme::kExactUnion;
      break;
    case v1::FPFH_SCHEME_RAW_POINTS:
      out.fpfh_scheme = perception::FpfhScheme::kRawPoints;
      break;
    default:
      return InvalidArgumentError("config.features.fpfh_scheme: unknown value " +
                                  std::to_string(in.fpfh_scheme()));
  }
  if (in.has_fpfh_radius()) out.fpfh_radius = in.fpfh_radius();
  return out;
}

void FeaturesToProto(const perception::FeatureConfig& in, v1::FeatureConfig* out) {
  out->set_colour(in.colour == perception::ColourConversion::kPaper2018
                      ? v1::COLOUR_VARIANT_PAPER2018
                      : v1::COLOUR_VARIANT_CORRECTED);
  switch (in.fpfh_scheme) {
    case perception::FpfhScheme::kExactUnion:
      out->set_fpfh_scheme(v1::FPFH_SCHEME_EXACT_UNION);
      break;
    case perception::FpfhScheme::kRawPoints:
      out->set_fpfh_scheme(v1::FPFH_SCHEME_RAW_POINTS);
      break;
    case perception::FpfhScheme::kSharedVoxels:
      out->set_fpfh_scheme(v1::FPFH_SCHEME_SHARED_VOXELS);
      break;
  }
  out->set_fpfh_radius(in.fpfh_radius);
}

StatusOr<perception::ChangeMethod> ChangeMethodFromProto(int method) {
  switch (method) {
    case v1::CHANGE_METHOD_UNSPECIFIED:
    case v1::CHANGE_METHOD_VISIBILITY:
      return perception::ChangeMethod::kVisibility;
    case v1::CHANGE_METHOD_PAPER2018:
      return perception::ChangeMethod::kPaper2018;
    default:
      return InvalidArgumentError("config.change_detector.method " + std::to_string(method) +
                                  " is not a ChangeMethod (0 to 2)");
  }
}

v1::ChangeMethod ChangeMethodToProto(perception::ChangeMethod method) {
  return method == perception::ChangeMethod::kPaper2018 ? v1::CHANGE_METHOD_PAPER2018
                                                        : v1::CHANGE_METHOD_VISIBILITY;
}

}  // namespace

StatusOr<cmm::Variant> VariantFromProto(int variant) {
  switch (variant) {
    case v1::CLASSIFIER_VARIANT_UNSPECIFIED:
    case v1::CLASSIFIER_VARIANT_CORRECTED:
      return cmm::Variant::kCorrected;
    case v1::CLASSIFIER_VARIANT_PAPER2018:
      return cmm::Variant::kPaper2018;
    case v1::CLASSIFIER_VARIANT_CORRECTED_V1:
      return cmm::Variant::kCorrectedV1;
    default:
      return InvalidArgumentError("config.classifier.variant " + std::to_string(variant) +
                                  " is not a ClassifierVariant (0 to 3)");
  }
}

v1::ClassifierVariant VariantToProto(cmm::Variant variant) {
  switch (variant) {
    case cmm::Variant::kPaper2018:
      return v1::CLASSIFIER_VARIANT_PAPER2018;
    case cmm::Variant::kCorrectedV1:
      return v1::CLASSIFIER_VARIANT_CORRECTED_V1;
    case cmm::Variant::kCorrected:
      break;
  }
  return v1::CLASSIFIER_VARIANT_CORRECTED;
}

StatusOr<session::SessionSettings> SettingsFromProto(const v1::SessionConfig& config) {
  session::SessionSettings settings;
  auto variant = VariantFromProto(config.classifier().variant());
  if (!variant.ok()) return variant.status();
  settings.classifier = cmm::CmmConfig::ForVariant(*variant);
  settings.exploration = exploration::ExplorationConfig::ForVariant(*variant);
  if (config.classifier().has_alpha()) settings.classifier.alpha = config.classifier().alpha();
  if (config.classifier().has_regularization()) {
    settings.classifier.regularization = config.classifier().regularization();
  }
  settings.classifier.seed = config.seed();

  auto& voxels = settings.perception.supervoxels;
  const v1::SupervoxelConfig& sv = config.supervoxels();
  if (sv.has_voxel_resolution()) voxels.voxel_resolution = sv.voxel_resolution();
  if (sv.has_seed_resolution()) voxels.seed_resolution = sv.seed_resolution();
  if (sv.has_colour_importance()) voxels.colour_importance = sv.colour_importance();
  if (sv.has_spatial_importance()) voxels.spatial_importance = sv.spatial_importance();
  if (sv.has_normal_importance()) voxels.normal_importance = sv.normal_importance();
  if (sv.has_min_voxels()) voxels.min_voxels = sv.min_voxels();
  if (config.has_workspace()) {
    const v1::WorkspaceBox& box = config.workspace();
    voxels.crop = {true,        box.min_x(), box.max_x(), box.min_y(),
                   box.max_y(), box.min_z(), box.max_z()};
  }
  auto& change = settings.perception.change;
  const v1::ChangeDetectorConfig& cd = config.change_detector();
  if (cd.has_octree_resolution()) change.octree_resolution = cd.octree_resolution();
  if (cd.has_depth_noise()) change.depth_noise = cd.depth_noise();
  if (cd.has_sor_mean_k()) change.sor_mean_k = cd.sor_mean_k();
  if (cd.has_sor_stddev_mul()) change.sor_stddev_mul = cd.sor_stddev_mul();
  if (cd.has_ror_radius()) change.ror_radius = cd.ror_radius();
  if (cd.has_ror_min_neighbours()) change.ror_min_neighbours = cd.ror_min_neighbours();
  if (cd.has_icp_max_iterations()) change.icp_max_iterations = cd.icp_max_iterations();
  if (cd.has_icp_max_correspondence()) change.icp_max_correspondence = cd.icp_max_correspondence();
  if (cd.has_max_fitness()) change.max_fitness = cd.max_fitness();
  StatusOr<perception::ChangeMethod> method = ChangeMethodFromProto(cd.method());
  if (!method.ok()) return method.status();
  change.method = *method;
  if (cd.has_noise_sigma_base()) change.noise.sigma_base = cd.noise_sigma_base();
  if (cd.has_noise_sigma_quadratic()) change.noise.sigma_quadratic = cd.noise_sigma_quadratic();
  if (cd.has_noise_reference_depth()) change.noise.reference_depth = cd.noise_reference_depth();
  if (cd.has_noise_quantisation()) change.noise.quantisation = cd.noise_quantisation();
  if (cd.has_tolerance_sigmas()) change.tolerance_sigmas = cd.tolerance_sigmas();
  if (cd.has_search_window()) change.search_window = cd.search_window();
  if (cd.has_min_vacated_fraction()) change.min_vacated_fraction = cd.min_vacated_fraction();
  if (cd.has_min_vacated_points()) change.min_vacated_points = cd.min_vacated_points();
  if (cd.has_colour_tolerance()) change.colour_tolerance = cd.colour_tolerance();
  if (cd.has_min_motion()) change.min_motion = cd.min_motion();
  if (cd.has_object_smooth_angle_deg()) {
    change.object_smooth_angle_deg = cd.object_smooth_angle_deg();
  }
  if (cd.has_compensate_camera_motion()) {
    change.compensate_camera_motion = cd.compensate_camera_motion();
  }
  if (cd.has_learn_moved_object()) change.learn_moved_object = cd.learn_moved_object();
  if (config.exploration().novelty()) {
    settings.exploration.diversity = exploration::Diversity::kNovelty;
  }
  if (config.exploration().has_class_balanced()) {
    settings.exploration.rule = config.exploration().class_balanced()
                                    ? exploration::ChoiceRule::kClassBalanced
                                    : exploration::ChoiceRule::kUncertainty;
  }
  if (config.exploration().has_random_share()) {
    settings.exploration.random_share = config.exploration().random_share();
  }
  if (Status valid = exploration::ValidateExploration(settings.exploration); !valid.ok()) {
    return InvalidArgumentError("config.exploration: " + valid.message());
  }
  StatusOr<perception::FeatureConfig> features = FeaturesFromProto(config.features());
  if (!features.ok()) return features.status();
  settings.perception.features = *features;
  if (config.feature_dimension() != 0) {
    settings.feature_dimension =
        static_cast<int>(std::min<std::uint32_t>(config.feature_dimension(), 1u << 20));
  }
  return settings;
}

v1::SessionConfig ProtoFromSettings(const session::SessionSettings& settings) {
  v1::SessionConfig config;
  auto* classifier = config.mutable_classifier();
  classifier->set_variant(VariantToProto(settings.classifier.variant));
  classifier->set_alpha(settings.classifier.alpha);
  classifier->set_regularization(settings.classifier.regularization);
  const auto& voxels = settings.perception.supervoxels;
  auto* sv = config.mutable_supervoxels();
  sv->set_voxel_resolution(voxels.voxel_resolution);
  sv->set_seed_resolution(voxels.seed_resolution);
  sv->set_colour_importance(voxels.colour_importance);
  sv->set_spatial_importance(voxels.spatial_importance);
  sv->set_normal_importance(voxels.normal_importance);
  sv->set_min_voxels(voxels.min_voxels);
  if (voxels.crop.enabled) {
    auto* box = config.mutable_workspace();
    box->set_min_x(voxels.crop.min_x), box->set_max_x(voxels.crop.max_x);
    box->set_min_y(voxels.crop.min_y), box->set_max_y(voxels.crop.max_y);
    box->set_min_z(voxels.crop.min_z), box->set_max_z(voxels.crop.max_z);
  }
  const auto& change = settings.perception.change;
  auto* cd = config.mutable_change_detector();
  cd->set_octree_resolution(change.octree_resolution);
  cd->set_depth_noise(change.depth_noise);
  cd->set_sor_mean_k(change.sor_mean_k);
  cd->set_sor_stddev_mul(change.sor_stddev_mul);
  cd->set_ror_radius(change.ror_radius);
  cd->set_ror_min_neighbours(change.ror_min_neighbours);
  cd->set_icp_max_iterations(change.icp_max_iterations);
  cd->set_icp_max_correspondence(change.icp_max_correspondence);
  cd->set_max_fitness(change.max_fitness);
  cd->set_method(ChangeMethodToProto(change.method));
  cd->set_noise_sigma_base(change.noise.sigma_base);
  cd->set_noise_sigma_quadratic(change.noise.sigma_quadratic);
  cd->set_noise_reference_depth(change.noise.reference_depth);
  cd->set_noise_quantisation(change.noise.quantisation);
  cd->set_tolerance_sigmas(change.tolerance_sigmas);
  cd->set_search_window(change.search_window);
  cd->set_min_vacated_fraction(change.min_vacated_fraction);
  cd->set_min_vacated_points(change.min_vacated_points);
  cd->set_compensate_camera_motion(change.compensate_camera_motion);
  cd->set_colour_tolerance(change.colour_tolerance);
  cd->set_object_smooth_angle_deg(change.object_smooth_angle_deg);
  cd->set_min_motion(change.min_motion);
  cd->set_learn_moved_object(change.learn_moved_object);
  FeaturesToProto(settings.perception.features, config.mutable_features());
  config.mutable_exploration()->set_novelty(settings.exploration.diversity ==
                                            exploration::Diversity::kNovelty);
  config.mutable_exploration()->set_random_share(settings.exploration.random_share);
  config.mutable_exploration()->set_class_balanced(settings.exploration.rule ==
                                                   exploration::ChoiceRule::kClassBalanced);
  config.set_seed(settings.classifier.seed);
  config.set_feature_dimension(static_cast<std::uint32_t>(settings.feature_dimension));
  return config;
}

void FillStats(const session::SessionStats& stats, v1::SessionStats* out) {
  out->set_non_moveable_samples(stats.samples[0]);
  out->set_moveable_samples(stats.samples[1]);
  out->set_non_moveable_components(stats.components[0]);
  out->set_moveable_components(stats.components[1]);
  out->set_frames(stats.frames);
  out->set_created_unix_ms(stats.created_unix_ms);
  out->set_last_used_unix_ms(stats.last_used_unix_ms);
}

void FillEvidence(const perception::ChangeEvidence& evidence, v1::ChangeEvidence* out) {
  out->set_moved(evidence.moved);
  out->set_difference_points(evidence.difference_points);
  out->set_after_statistical(evidence.after_statistical);
  out->set_after_radius(evidence.after_radius);
  out->set_icp_converged(evidence.icp_converged);
  out->set_icp_fitness(evidence.icp_fitness);
  out->set_elapsed_ms(evidence.elapsed_ms);
  out->set_method(ChangeMethodToProto(evidence.method));
  out->set_target_points(evidence.target_points);
  out->set_supported_points(evidence.supported_points);
  out->set_vacated_points(evidence.vacated_points);
  out->set_occluded_points(evidence.occluded_points);
  out->set_camera_rotation_deg(evidence.camera_rotation_deg);
  out->set_camera_translation_m(evidence.camera_translation_m);
  out->set_object_supervoxels(evidence.object_supervoxels);
  out->set_object_points(evidence.object_points);
  out->set_object_supported_points(evidence.object_supported_points);
  out->set_object_vacated_points(evidence.object_vacated_points);
  out->set_object_occluded_points(evidence.object_occluded_points);
  out->set_vacated_beyond_motion_points(evidence.vacated_beyond_motion_points);
  out->set_object_vacated_beyond_motion_points(evidence.object_vacated_beyond_motion_points);
  out->set_object_motion_fitted(evidence.object_motion_fitted);
  out->set_object_motion_translation_m(evidence.object_motion_translation_m);
  out->set_object_motion_rotation_deg(evidence.object_motion_rotation_deg);
  out->set_carried_supported_points(evidence.carried_supported_points);
  out->set_carried_vacated_points(evidence.carried_vacated_points);
  out->set_carried_occluded_points(evidence.carried_occluded_points);
  out->mutable_moved_supervoxels()->Add(evidence.moved_supervoxels.begin(),
                                        evidence.moved_supervoxels.end());
}

session::EncodedCloud EncodedCloudOf(const v1::Cloud& cloud) {
  session::EncodedCloud encoded;
  switch (cloud.encoding_case()) {
    case v1::Cloud::kPcd:
      encoded.format = session::EncodedCloud::Format::kPcd;
      encoded.bytes = cloud.pcd();
      break;
    case v1::Cloud::kPacked:
      encoded.format = session::EncodedCloud::Format::kPacked;
      encoded.bytes = cloud.packed().points();
      encoded.width = cloud.packed().width();
      encoded.height = cloud.packed().height();
      break;
    case v1::Cloud::ENCODING_NOT_SET:
      break;
  }
  return encoded;
}

std::string StoredConfigOf(const session::SessionSettings& settings) {
  return ProtoFromSettings(settings).SerializeAsString();
}

StatusOr<session::SessionSettings> SettingsOfStoredSession(const session::SessionRecord& record) {
  v1::SessionConfig config;
  if (!config.ParseFromString(record.config)) {
    return DataLossError("session " + record.id + ": its stored configuration does not parse");
  }
  return SettingsFromProto(config);
}

}  // namespace relmap::service
