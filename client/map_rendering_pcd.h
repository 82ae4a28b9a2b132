// The map renderings of map_rendering.h over the points of a PCD file (the relmap CLI
// reads the PCD it sent with common/pcd, the reader the server decodes with, so that the
// point labels line up), and the coloured PCD.
#pragma once

#include <string>
#include <vector>

#include "common/pcd/pcd_reader.h"
#include "common/status.h"
#include "map_rendering.h"
#include "relmap/v1/relevance_service.pb.h"

namespace relmap::client {

// ColourPoints of map_rendering.h over `cloud`'s points in their own colours.
StatusOr<std::vector<image::ColouredPoint>> ColourPoints(const pcd::Points& cloud,
                                                         const v1::ComputeMapsResponse& maps,
                                                         MapKind kind);

Status WriteMapPng(const pcd::Points& cloud, const v1::ComputeMapsResponse& maps, MapKind kind,
                   const std::string& path);
// The cloud with each point in its relevance colour, as a binary PCD.
Status WriteRelevancePcd(const pcd::Points& cloud, const v1::ComputeMapsResponse& maps,
                         const std::string& path);

}  // namespace relmap::client
