// Every supervoxel of every frame of the real static Kinect sequences as a push target,
// judged by the change detector against each other frame: how many it calls "moved" (none
// should be; the scene did not change, a hand-held camera moved 0.7-1.2 degrees). The CTest
// check (ChangeDetector.SeesNoChangeBetweenFramesOfAStaticScene) samples every 30th
// supervoxel; this program scans them all and lists the ones called moved.
//
//   static_change_scan [--method visibility|paper2018] [--data DIR]
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "common/command_line.h"
#include "perception/change_detector.h"
#include "perception/decode.h"
#include "perception/supervoxels.h"

namespace rp = relmap::perception;

namespace {

int Main(int argc, char** argv) {
  std::string data = RELMAP_BENCHMARK_DATA_DIR;
  rp::ChangeDetectorConfig config;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--data") == 0) {
      data = argv[i + 1];
    } else if (std::strcmp(argv[i], "--method") == 0) {
      config.method = std::strcmp(argv[i + 1], "paper2018") == 0 ? rp::ChangeMethod::kPaper2018
                                                                 : rp::ChangeMethod::kVisibility;
    } else {
      std::fprintf(stderr, "usage: %s [--method visibility|paper2018] [--data DIR]\n", argv[0]);
      return 2;
    }
  }
  std::vector<rp::Cloud> clouds;
  for (int i = 1; i <= 3; ++i) {
    const std::string path = data + "/kinect_static_seq_" + std::to_string(i) + ".pcd";
    relmap::StatusOr<rp::Cloud> cloud = rp::LoadPcdFile(path);
    if (!cloud.ok()) {
      std::fprintf(stderr, "%s: %s\n", path.c_str(), std::string(cloud.status().message()).c_str());
      return 1;
    }
    clouds.push_back(std::move(cloud).value());
  }
  std::printf("| before -> after | targets | called moved |\n|---|---|---|\n");
  std::size_t targets = 0, moved = 0;
  std::string listed;
  for (std::size_t b = 0; b < clouds.size(); ++b) {
    const relmap::StatusOr<rp::Segmentation> seg =
        rp::ExtractSupervoxels(clouds[b], rp::SupervoxelConfig{});
    if (!seg.ok()) return 1;
    for (std::size_t a = 0; a < clouds.size(); ++a) {
      if (a == b) continue;
      std::size_t pair_moved = 0;
      for (std::size_t s = 0; s < seg->supervoxels.size(); ++s) {
        const rp::Supervoxel& target = seg->supervoxels[s];
        const relmap::StatusOr<rp::ChangeEvidence> e = rp::DetectChange(
            clouds[b], clouds[a], seg->supervoxels, static_cast<std::uint32_t>(s), config);
        if (!e.ok() || !e->moved) continue;
        ++pair_moved;
        char line[256];
        std::snprintf(line, sizeof line,
                      "seq_%zu -> seq_%zu, supervoxel %zu at (%.2f, %.2f, %.2f) m: %zu points, "
                      "%zu still there, %zu vacated, %zu occluded; object of %zu supervoxels, %zu "
                      "points, %zu still there, %zu vacated\n",
                      b + 1, a + 1, s, target.centroid.x(), target.centroid.y(),
                      target.centroid.z(), e->target_points, e->supported_points, e->vacated_points,
                      e->occluded_points, e->object_supervoxels, e->object_points,
                      e->object_supported_points, e->object_vacated_points);
        listed += line;
      }
      std::printf("| seq_%zu -> seq_%zu | %zu | %zu |\n", b + 1, a + 1, seg->supervoxels.size(),
                  pair_moved);
      targets += seg->supervoxels.size();
      moved += pair_moved;
    }
  }
  std::printf("| all | %zu | %zu |\n\n%s", targets, moved, listed.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return relmap::tools::ExitCodeOf("static_change_scan", [&] { return Main(argc, argv); });
}
