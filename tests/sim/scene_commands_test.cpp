// relmap-sim scenes and relmap-sim render, called as relmap-sim's main calls them
// (argv from the command word on).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/exec_argv.h"
#include "sim_commands.h"

namespace relmap::sim {
namespace {

int RunCommand(int (*command)(int, char**), std::vector<std::string> words) {
  std::vector<char*> argv = ExecArgv(words);
  return command(static_cast<int>(words.size()), argv.data());
}

std::string TempPng(const char* name) {
  return (std::filesystem::temp_directory_path() / name).string();
}

TEST(ScenesCommand, ListsTheShippedScenes) {
  EXPECT_EQ(RunCommand(RunScenesCommand, {"scenes"}), 0);
}

TEST(ScenesCommand, RefusesArguments) {
  EXPECT_EQ(RunCommand(RunScenesCommand, {"scenes", "--verbose"}), 2);
}

TEST(RenderCommand, WritesThePngOfTheCameraView) {
  const std::string png = TempPng("relmap_render_test.png");
  std::filesystem::remove(png);
  EXPECT_EQ(RunCommand(RunRenderCommand, {"render", "--scene", "MoveableBalls", "--png", png,
                                          "--seed", "4", "--width", "160", "--height", "120"}),
            0);
  std::ifstream in(png, std::ios::binary);
  char signature[8] = {};
  in.read(signature, 8);
  EXPECT_EQ(std::string(signature + 1, 3), "PNG");
  std::filesystem::remove(png);
}

TEST(RenderCommand, BadArgumentsExitWithCodeTwo) {
  const std::string png = TempPng("relmap_render_bad.png");
  EXPECT_EQ(RunCommand(RunRenderCommand, {"render", "--png", png}), 2);  // no --scene
  EXPECT_EQ(RunCommand(RunRenderCommand, {"render", "--scene", "NoSuchScene", "--png", png}), 2);
  EXPECT_EQ(RunCommand(RunRenderCommand,
                       {"render", "--scene", "MoveableBalls", "--png", png, "--seed", "-3"}),
            2);
  EXPECT_EQ(RunCommand(RunRenderCommand,
                       {"render", "--scene", "MoveableBalls", "--png", png, "--width", "100"}),
            2);  // --width without --height
  EXPECT_EQ(RunCommand(RunRenderCommand, {"render", "--scene"}), 2);
  EXPECT_FALSE(std::filesystem::exists(png));
}

}  // namespace
}  // namespace relmap::sim
