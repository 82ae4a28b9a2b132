// The maps of a frame drawn over the points that were sent: PNG pictures. Relevance
// runs black (not moveable) → yellow (moveable) as in the paper's figures; the choice
// map runs blue → red, scaled to the frame's most likely target. The drawn target is
// outlined in green. Free of the perception layer: the points come as plain coloured
// points (the simulator's camera frames); map_rendering_cloud.h adds decoded clouds.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/image/point_raster.h"
#include "common/status.h"
#include "relmap/v1/relevance_service.pb.h"

namespace relmap::client {

enum class MapKind { kRelevance, kChoice };

// Eq. (class_est) P(moveable) ∈ [0, 1] → (255·p, 255·p, 0).
image::Rgb RelevanceColour(double relevance);
// choice / max_choice ∈ [0, 1] → (255·t, 0, 255·(1 − t)).
image::Rgb ChoiceColour(double choice, double max_choice);

// `points` are the cloud that was sent, row-major, `width` × `height` of them, each in
// its own colour (NaN x for a hole). One coloured point per point: its supervoxel's
// map colour, grey (the point's own brightness) outside every supervoxel, the target's
// border in green. INVALID_ARGUMENT if `points` is not `width` × `height` long, if
// `maps` does not label exactly these points (another cloud than the one sent) or
// names a supervoxel it does not list.
StatusOr<std::vector<image::ColouredPoint>> ColourPoints(
    std::uint32_t width, std::uint32_t height, const std::vector<image::ColouredPoint>& points,
    const v1::ComputeMapsResponse& maps, MapKind kind);

// The coloured points as a PNG: pixel for pixel when organized (height > 1).
Status WriteMapPng(std::uint32_t width, std::uint32_t height,
                   const std::vector<image::ColouredPoint>& points,
                   const v1::ComputeMapsResponse& maps, MapKind kind, const std::string& path);

}  // namespace relmap::client
