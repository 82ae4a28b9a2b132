// The target: the server's draw, or a uniform draw that never picks a supervoxel the
// server could not learn from.
#include "target_choice.h"

#include <gtest/gtest.h>

#include <set>

#include "seeds.h"

namespace relmap::sim {
namespace {

// Three supervoxels with ids 4, 7, 9; the one with id 7 has unusable features
// (relevance 0.5, choice 0).
v1::ComputeMapsResponse ThreeSupervoxels() {
  v1::ComputeMapsResponse maps;
  for (const auto& [id, relevance, choice] :
       {std::tuple{4u, 0.2, 0.6}, std::tuple{7u, 0.5, 0.0}, std::tuple{9u, 0.9, 0.4}}) {
    v1::Supervoxel* s = maps.add_supervoxels();
    s->set_id(id), s->set_relevance(relevance), s->set_choice(choice);
  }
  maps.set_unusable_supervoxels(1);
  maps.set_target_supervoxel_id(9);
  return maps;
}

TEST(ChooseTarget, TakesTheServersDrawByItsIndex) {
  EXPECT_EQ(ChooseTarget(ThreeSupervoxels(), TargetSampling::kChoice, 0).value(), 2);
}

TEST(ChooseTarget, NoServerTargetMeansNoTarget) {
  v1::ComputeMapsResponse maps = ThreeSupervoxels();
  maps.clear_target_supervoxel_id();
  EXPECT_FALSE(ChooseTarget(maps, TargetSampling::kChoice, 0).value().has_value());
}

TEST(ChooseTarget, AServerTargetOutsideTheMapsIsAnError) {
  v1::ComputeMapsResponse maps = ThreeSupervoxels();
  maps.set_target_supervoxel_id(5);
  EXPECT_EQ(ChooseTarget(maps, TargetSampling::kChoice, 0).status().code(),
            StatusCode::kInvalidArgument);
}

TEST(ChooseTarget, RandomDrawsCoverTheUsableSupervoxelsOnly) {
  std::set<int> drawn;
  for (int i = 0; i < 200; ++i) {
    drawn.insert(*ChooseTarget(ThreeSupervoxels(), TargetSampling::kRandom,
                               IterationSeed(1, SeedStream::kRandomTarget, i))
                      .value());
  }
  EXPECT_EQ(drawn, (std::set<int>{0, 2}));
}

TEST(ChooseTarget, WithoutUnusableSupervoxelsEveryOneCanBeDrawn) {
  v1::ComputeMapsResponse maps = ThreeSupervoxels();
  maps.set_unusable_supervoxels(0);  // then relevance 0.5 with choice 0 is a usable one
  std::set<int> drawn;
  for (int i = 0; i < 200; ++i) {
    drawn.insert(
        *ChooseTarget(maps, TargetSampling::kRandom, IterationSeed(1, SeedStream::kRandomTarget, i))
             .value());
  }
  EXPECT_EQ(drawn, (std::set<int>{0, 1, 2}));
}

}  // namespace
}  // namespace relmap::sim
