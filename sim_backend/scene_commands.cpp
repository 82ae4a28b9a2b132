// relmap-sim scenes and relmap-sim render: the shipped scenes, and a scene's
// camera view with the moveable bodies tinted and outlined, to check it by eye.
//
// Both accept argv with or without the program and command words in front
// (["relmap-sim", "render", "--scene", ...] or ["render", "--scene", ...]): words
// before the first flag are skipped.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>

#include "common/image/image.h"
#include "common/image/point_raster.h"
#include "ode_scene.h"
#include "scene_file.h"
#include "scene_settings.h"
#include "sim_commands.h"

namespace relmap::sim {
namespace {

constexpr char kRenderUsage[] =
    "usage: relmap-sim render --scene <name|file.json> --png <out.png> [--seed S]\n"
    "                         [--width W --height H] [--plain]\n"
    "  The scene's camera view; moveable bodies tinted and outlined in magenta\n"
    "  (--plain: the camera's colours only). Default seed 1, size from the scene.\n";
constexpr char kScenesUsage[] =
    "usage: relmap-sim scenes\n"
    "  Lists the shipped scenes: name, file, bodies, description.\n";

constexpr image::Rgb kOverlay = {255, 0, 255};
constexpr image::Rgb kHole = {0, 0, 0};
constexpr double kTint = 0.35;

// `--name value` flags after the leading words; `switches` take no value.
// False (after printing why) on a stray word, an unknown flag or a missing value.
bool ParseFlags(int argc, char** argv, const char* command,
                const std::map<std::string, bool>& known, std::map<std::string, std::string>* out) {
  int i = 0;
  while (i < argc && std::string(argv[i]).rfind("--", 0) != 0) ++i;
  for (; i < argc; ++i) {
    const std::string flag = argv[i];
    const auto it = known.find(flag);
    if (it == known.end()) {
      FailCommand(command, "unknown argument '" + flag + "'", 2);
      return false;
    }
    if (!it->second) {
      (*out)[flag].assign(1, '1');  // not = "1": GCC 12 warns falsely (-Wrestrict)
      continue;
    }
    if (i + 1 >= argc) {
      FailCommand(command, flag + " needs a value", 2);
      return false;
    }
    (*out)[flag] = argv[++i];
  }
  return true;
}

bool ParseUnsigned(const std::string& text, std::uint64_t max, std::uint64_t* value) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) return false;
  try {
    *value = std::stoull(text);
  } catch (const std::out_of_range&) {
    return false;
  }
  return *value <= max;
}

image::Rgb Blend(const image::Rgb& a, const image::Rgb& b, double t) {
  image::Rgb out;
  for (int i = 0; i < 3; ++i)
    out[i] = static_cast<std::uint8_t>(std::lround((1 - t) * a[i] + t * b[i]));
  return out;
}

// The frame as coloured points; with the overlay, moveable bodies tinted and
// their silhouettes (pixels next to another body or a hole) in the overlay colour.
std::vector<image::ColouredPoint> OverlayPoints(const CameraFrame& frame, const OdeScene& scene,
                                                bool overlay) {
  std::vector<image::ColouredPoint> points(frame.points.size());
  const auto w = static_cast<int>(frame.width), h = static_cast<int>(frame.height);
  for (int v = 0; v < h; ++v) {
    for (int u = 0; u < w; ++u) {
      const std::size_t i = static_cast<std::size_t>(v) * w + u;
      const CameraPoint& p = frame.points[i];
      image::ColouredPoint& out = points[i];
      out.x = p.x;
      out.y = p.y;
      out.z = p.z;
      out.colour = {p.r, p.g, p.b};
      const std::int32_t id = frame.body_ids[i];
      if (!overlay || !scene.IsMoveable(id)) continue;
      bool edge = false;
      for (const auto& [du, dv] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        const int nu = u + du, nv = v + dv;
        if (nu < 0 || nv < 0 || nu >= w || nv >= h) continue;
        edge = edge || frame.body_ids[static_cast<std::size_t>(nv) * w + nu] != id;
      }
      out.colour = edge ? kOverlay : Blend(out.colour, kOverlay, kTint);
    }
  }
  return points;
}

}  // namespace

int RunScenesCommand(int argc, char** argv) {
  std::map<std::string, std::string> flags;
  if (!ParseFlags(argc, argv, "scenes", {{"--help", false}}, &flags)) {
    std::fputs(kScenesUsage, stderr);
    return 2;
  }
  if (flags.count("--help") != 0) {
    std::fputs(kScenesUsage, stdout);
    return 0;
  }
  const std::vector<std::string> files = ShippedSceneFiles();
  if (files.empty()) return FailCommand("scenes", "no scene files in " + ScenesDirectory(), 2);
  int exit_code = 0;
  std::printf("%-20s %-26s %7s %8s  %s\n", "scene", "file", "static", "moveable", "description");
  for (const std::string& path : files) {
    StatusOr<SceneFile> file = ReadSceneFile(path);
    if (!file.ok()) {
      exit_code = FailCommand("scenes", file.status().message(), 2);
      continue;
    }
    const Scene& scene = file->scene;
    std::uint32_t moveable = 0;
    for (const Body& object : scene.objects()) moveable += ObjectCount(object);
    std::printf("%-20s %-26s %7d %8u  %s\n", scene.name().c_str(),
                std::filesystem::path(path).filename().string().c_str(), scene.static_bodies_size(),
                moveable, scene.description().c_str());
  }
  std::printf("(folder: %s)\n", ScenesDirectory().c_str());
  return exit_code;
}

int RunRenderCommand(int argc, char** argv) {
  std::map<std::string, std::string> flags;
  const std::map<std::string, bool> known = {
      {"--scene", true},  {"--png", true},    {"--seed", true}, {"--width", true},
      {"--height", true}, {"--plain", false}, {"--help", false}};
  if (!ParseFlags(argc, argv, "render", known, &flags)) {
    std::fputs(kRenderUsage, stderr);
    return 2;
  }
  if (flags.count("--help") != 0) {
    std::fputs(kRenderUsage, stdout);
    return 0;
  }
  if (flags.count("--scene") == 0 || flags.count("--png") == 0) {
    std::fputs(kRenderUsage, stderr);
    return FailCommand("render", "--scene and --png are required", 2);
  }
  std::uint64_t seed = 1, width = 0, height = 0;
  if (flags.count("--seed") != 0 && !ParseUnsigned(flags["--seed"], ~std::uint64_t{0}, &seed)) {
    return FailCommand("render",
                       "--seed expects a non-negative integer, got '" + flags["--seed"] + "'", 2);
  }
  if (flags.count("--width") != flags.count("--height")) {
    return FailCommand("render", "--width and --height go together", 2);
  }
  if (flags.count("--width") != 0 &&
      (!ParseUnsigned(flags["--width"], 4096, &width) ||
       !ParseUnsigned(flags["--height"], 4096, &height) || width == 0 || height == 0)) {
    return FailCommand("render", "--width and --height expect 1..4096 pixels", 2);
  }

  const auto load_start = std::chrono::steady_clock::now();
  StatusOr<std::unique_ptr<OdeScene>> loaded = OdeScene::Load(flags["--scene"], seed);
  if (!loaded.ok()) return FailCommand("render", loaded.status().message(), 2);
  OdeScene& scene = **loaded;
  if (width != 0) {
    scene.SetImageSize(static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height));
  }
  const auto capture_start = std::chrono::steady_clock::now();
  const CameraFrame frame = scene.Capture();
  const auto capture_end = std::chrono::steady_clock::now();

  const bool overlay = flags.count("--plain") == 0;
  const image::Image picture = image::RasterisePoints(OverlayPoints(frame, scene, overlay),
                                                      frame.width, frame.height, kHole);
  if (Status written = image::WritePng(picture, flags["--png"]); !written.ok()) {
    return FailCommand("render", written.message(), 1);
  }
  const auto ms = [](auto d) { return std::chrono::duration<double, std::milli>(d).count(); };
  std::printf(
      "%s (seed %llu): %ux%u, %zu moveable bodies, load+respawn %.1f ms, capture %.1f ms "
      "-> %s\n",
      scene.name().c_str(), static_cast<unsigned long long>(seed), frame.width, frame.height,
      scene.moveable_bodies().size(), ms(capture_start - load_start),
      ms(capture_end - capture_start), flags["--png"].c_str());
  return 0;
}

}  // namespace relmap::sim
