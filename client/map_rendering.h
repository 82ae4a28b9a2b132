// The maps of a frame drawn over the cloud that was sent: PNG pictures and a coloured
// PCD. Relevance runs black (not moveable) → yellow (moveable) as in the paper's
// figures; the choice map runs blue → red, scaled to the frame's most likely target.
// The drawn target is outlined in green.
#pragma once

#include <string>
#include <vector>

#include "common/status.h"
#include "image/point_raster.h"
#include "perception/cloud.h"
#include "relmap/v1/relevance_service.pb.h"

namespace relmap::client {

enum class MapKind { kRelevance, kChoice };

// Eq. (class_est) P(moveable) ∈ [0, 1] → (255·p, 255·p, 0).
image::Rgb RelevanceColour(double relevance);
// choice / max_choice ∈ [0, 1] → (255·t, 0, 255·(1 − t)).
image::Rgb ChoiceColour(double choice, double max_choice);

// One coloured point per point of `cloud`: its supervoxel's map colour, grey (the
// point's own brightness) outside every supervoxel, the target's border in green.
// INVALID_ARGUMENT if `maps` does not label exactly the points of `cloud` (another
// file than the one sent) or names a supervoxel it does not list.
StatusOr<std::vector<image::ColouredPoint>> ColourPoints(const perception::Cloud& cloud,
                                                         const v1::ComputeMapsResponse& maps,
                                                         MapKind kind);

Status WriteMapPng(const perception::Cloud& cloud, const v1::ComputeMapsResponse& maps,
                   MapKind kind, const std::string& path);
// The cloud with each point in its relevance colour, as a binary PCD.
Status WriteRelevancePcd(const perception::Cloud& cloud, const v1::ComputeMapsResponse& maps,
                         const std::string& path);

}  // namespace relmap::client
