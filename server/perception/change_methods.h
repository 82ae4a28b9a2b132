// The two ways of labelling a push (change_detector.h dispatches): each fills the evidence
// of its method and `moved`. The target is checked (points, finite voxels) before.
#pragma once

#include <vector>

#include "perception/change_detector.h"

namespace relmap::perception {

// `object` lists the supervoxels of the target's object other than the target (checked:
// their points lie in `before`); empty, the object is the target alone.
void DetectByVisibility(const Cloud& before, const Cloud& after, const Supervoxel& target,
                        const std::vector<const Supervoxel*>& object,
                        const ChangeDetectorConfig& config, ChangeEvidence& evidence);

// Throws what PCL throws.
void DetectByOctreeIcp(const Cloud& before, const Cloud& after, const Supervoxel& target,
                       const ChangeDetectorConfig& config, ChangeEvidence& evidence);

}  // namespace relmap::perception
