// The two ways of labelling a push (change_detector.h dispatches): each fills the evidence
// of its method and `moved`. The target is checked (points, finite voxels) before.
#pragma once

#include "perception/change_detector.h"

namespace relmap::perception {

void DetectByVisibility(const Cloud& before, const Cloud& after, const Supervoxel& target,
                        const ChangeDetectorConfig& config, ChangeEvidence& evidence);

// Throws what PCL throws.
void DetectByOctreeIcp(const Cloud& before, const Cloud& after, const Supervoxel& target,
                       const ChangeDetectorConfig& config, ChangeEvidence& evidence);

}  // namespace relmap::perception
