// The run directory: what relmap-robot records of every iteration and replay reads
// back. <run-dir>/session.json, then per iteration <run-dir>/<000001>/: before.pcd
// (or before.cloud, a serialised v1::Cloud for packed clouds), maps.json (without
// point labels), target.json, driver.json, after.pcd|after.cloud, label.json (the
// PostOutcome answer), truth.json when the source knows it, status.json.
#pragma once

#include <google/protobuf/message.h>

#include <string>
#include <vector>

#include "common/status.h"
#include "relmap/v1/relevance_service.pb.h"

namespace relmap::robot {

// <run-dir>/<iteration, six digits>.
std::string IterationDirectory(const std::string& run_dir, int iteration);
// The iterations recorded in `run_dir`, ascending.
std::vector<int> RecordedIterations(const std::string& run_dir);

// `message` as JSON (proto field names, every field) into `path`, atomically.
Status WriteJson(const std::string& path, const google::protobuf::Message& message);
// NOT_FOUND when `path` is missing, INVALID_ARGUMENT when it does not parse.
Status ReadJson(const std::string& path, google::protobuf::Message* message);
// `cloud` as <directory>/<stem>.pcd or <stem>.cloud.
Status WriteCloud(const std::string& directory, const std::string& stem, const v1::Cloud& cloud);
// NOT_FOUND when neither file exists.
StatusOr<v1::Cloud> ReadCloud(const std::string& directory, const std::string& stem);
// Raw bytes into `path`, atomically (written beside it, then renamed).
Status WriteFile(const std::string& path, const std::string& bytes);

}  // namespace relmap::robot
