// Renders a frame's segmentation to a PNG: organized clouds pixel for pixel, others as a
// top-down (x-z) projection. One colour per supervoxel, black for unlabelled points.
#pragma once

#include <string>

#include "common/status.h"
#include "perception/frame.h"

namespace relmap::perception {

Status WriteSegmentationPng(const Frame& frame, const std::string& path);

}  // namespace relmap::perception
