// Scene files: where the shipped ones are, how a name or a path finds one, and
// reading one (JSON -> Scene message -> ValidateScene).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "common/status.h"
#include "scene_schema.pb.h"

namespace relmap::sim {

// The folder of the shipped scenes: $RELMAP_SIM_SCENES_DIR if set, otherwise the
// source tree's sim_backend/scenes (compiled in).
std::string ScenesDirectory();

// The shipped scene files (<dir>/*.json), sorted by name.
std::vector<std::string> ShippedSceneFiles();

// `name_or_path` as a file: an existing file as given, otherwise
// <ScenesDirectory()>/<name_or_path>.json; NotFound (listing the shipped names)
// when neither exists.
StatusOr<std::string> FindSceneFile(const std::string& name_or_path);

// A scene file's JSON text parsed and validated; `file_label` (usually the file's
// name) starts every error message.
StatusOr<Scene> ParseScene(std::string_view json, const std::string& file_label);

struct SceneFile {
  std::string path;
  Scene scene;
};
// FindSceneFile, then ParseScene of its contents.
StatusOr<SceneFile> ReadSceneFile(const std::string& name_or_path);

}  // namespace relmap::sim
