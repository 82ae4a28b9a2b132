// The simulator as a stand-in robot.
#include "sim_robot.h"

#include <memory>

#include "ground_truth.h"
#include "ode_scene.h"
#include "packed_cloud.h"
#include "seeds.h"
#include "simulated_robot.h"

namespace relmap::robot {
namespace {

class OdeRobot final : public SimulatedRobot {
 public:
  OdeRobot(std::unique_ptr<sim::OdeScene> scene, std::uint64_t seed)
      : scene_(std::move(scene)), seed_(seed) {}
  std::unique_ptr<CloudSource> Source() override { return std::make_unique<SimSource>(*scene_); }
  std::unique_ptr<PusherDriver> Driver() override {
    return std::make_unique<SimDriver>(*scene_, seed_);
  }

 private:
  std::unique_ptr<sim::OdeScene> scene_;
  std::uint64_t seed_;
};

}  // namespace

StatusOr<std::unique_ptr<SimulatedRobot>> MakeSimulatedRobot(const SimConfig& config) {
  StatusOr<std::unique_ptr<sim::OdeScene>> loaded =
      sim::OdeScene::Load(config.scene(), config.seed());
  if (!loaded.ok()) return loaded.status();
  std::unique_ptr<sim::OdeScene> scene = std::move(loaded).value();
  if (config.width() > 0 && config.height() > 0) {
    scene->SetImageSize(config.width(), config.height());
  }
  return std::unique_ptr<SimulatedRobot>(
      std::make_unique<OdeRobot>(std::move(scene), config.seed()));
}

StatusOr<std::optional<SourceFrame>> SimSource::Next() {
  auto frame = std::make_shared<sim::CameraFrame>(scene_.Capture());
  SourceFrame captured;
  captured.cloud = sim::PackCloud(*frame);
  sim::SimulatedScene* scene = &scene_;
  captured.truth = [frame, scene](const v1::ComputeMapsResponse& maps) {
    return sim::SupervoxelGroundTruth(
        *frame, maps, [scene](std::int32_t body) { return scene->IsMoveable(body); });
  };
  return std::optional<SourceFrame>(std::move(captured));
}

StatusOr<PushOutcome> SimDriver::Push(const DriverRequest& target) {
  // One push seed per (iteration, attempt): attempts of one iteration differ.
  const int draw = static_cast<int>(target.iteration() * 16 + target.attempt());
  const Eigen::Vector3f centroid(target.centroid().x(), target.centroid().y(),
                                 target.centroid().z());
  const sim::PushReport report =
      scene_.Push(centroid, sim::IterationSeed(seed_, sim::SeedStream::kPush, draw));
  PushOutcome outcome;
  outcome.result = report.executed ? PushResult::kDone : PushResult::kUnreachable;
  outcome.message = report.executed ? std::to_string(report.moved_bodies.size()) + " bodies moved"
                                    : "every approach direction was blocked";
  return outcome;
}

}  // namespace relmap::robot
