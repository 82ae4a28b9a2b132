// Optional fields of relmap-perception's JSON line about a frame's features.
#pragma once

#include <string>

#include "perception/features.h"
#include "perception/frame.h"
#include "perception/perception_config.h"

namespace relmap::tools {

// ",\"fpfh_l1_mean\":…,\"fpfh_l1_max\":…,\"fpfh_abs_max\":…": the L1 distance per
// supervoxel between the shared-voxel and the exact FPFH on `frame`'s segmentation.
std::string FpfhDeviationJson(const perception::Frame& frame,
                              const perception::PerceptionConfig& config);

// ",\"mean_feature\":[…],\"fpfh_block_max\":[…]": the mean feature over the finite
// rows, and the largest value of each of its three FPFH blocks: how peaked the
// frame's FPFH are, comparable with another pipeline's means.
std::string FeatureStatsJson(const perception::FeatureMatrix& features);

}  // namespace relmap::tools
