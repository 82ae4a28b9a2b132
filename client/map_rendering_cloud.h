// The map renderings of map_rendering.h over a cloud decoded by the perception layer
// (the relmap CLI decodes the PCD it sent with the server's own decoder, so that the
// point labels line up), and the coloured PCD.
#pragma once

#include <string>
#include <vector>

#include "common/status.h"
#include "map_rendering.h"
#include "perception/cloud.h"
#include "relmap/v1/relevance_service.pb.h"

namespace relmap::client {

// ColourPoints of map_rendering.h over the points of `cloud` in their own colours.
StatusOr<std::vector<image::ColouredPoint>> ColourPoints(const perception::Cloud& cloud,
                                                         const v1::ComputeMapsResponse& maps,
                                                         MapKind kind);

Status WriteMapPng(const perception::Cloud& cloud, const v1::ComputeMapsResponse& maps,
                   MapKind kind, const std::string& path);
// The cloud with each point in its relevance colour, as a binary PCD.
Status WriteRelevancePcd(const perception::Cloud& cloud, const v1::ComputeMapsResponse& maps,
                         const std::string& path);

}  // namespace relmap::client
