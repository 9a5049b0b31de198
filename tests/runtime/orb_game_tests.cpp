// candela-orb-game driven headless by recorded input, as its replays are meant to be used:
// the score after N frames, winning, losing, restarting, and bad input refused clearly.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "full_filesystem.h"
#include "run_command.h"

namespace {

using candela::testing::runCommand;
using candela::testing::RunResult;

// ORB_GAME_EXECUTABLE in the environment tests another build of the game (scripts/test runs
// these tests against the game built outside the tree on an installed engine).
std::string gameExecutable() {
    const char* other = std::getenv("ORB_GAME_EXECUTABLE");
    return other && *other ? other : ORB_GAME_EXECUTABLE;
}

RunResult runGame(const std::string& args) {
    return runCommand(gameExecutable() + " " + args);
}

std::filesystem::path tempDir() {
    auto dir = std::filesystem::path(testing::TempDir()) / "candela_orb_game";
    std::filesystem::create_directories(dir);
    return dir;
}

const std::string kReplays = std::string(ORB_GAME_DIR) + "/replays/";

nlohmann::json play(const std::string& replay, int frames, const std::string& name) {
    auto state = tempDir() / (name + ".json");
    std::filesystem::remove(state);
    RunResult r = runGame("--headless --size 32x24 --frames " + std::to_string(frames) +
                          " --input " + kReplays + replay + " --state " + state.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(state);
    std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    return nlohmann::json::parse(text, nullptr, false);
}

}  // namespace

TEST(OrbGame, ScoreAfterNFramesFollowsTheReplay) {
    // 95 frames east along the south wall: the sparks at x = 0 and x = 5 are collected.
    nlohmann::json s = play("win.input", 95, "partial");
    ASSERT_TRUE(s.is_object());
    EXPECT_EQ(s["status"], "playing");
    EXPECT_EQ(s["score"], 20);
    EXPECT_EQ(s["collected"], 2);
    EXPECT_EQ(s["total"], 8);
}

TEST(OrbGame, CollectingEverySparkWins) {
    nlohmann::json s = play("win.input", 400, "win");
    ASSERT_TRUE(s.is_object());
    EXPECT_EQ(s["status"], "won");
    EXPECT_EQ(s["reason"], "all sparks collected");
    EXPECT_EQ(s["score"], 80);
    // The game stops the clock when it ends: 343 frames of 1/30 s (frame 0 has no time step).
    EXPECT_NEAR(s["elapsed_seconds"].get<double>(), 343.0 / 30.0, 1e-6);
}

TEST(OrbGame, TouchingASentinelLosesAndRRestarts) {
    nlohmann::json lost = play("lose_restart.input", 140, "lost");
    ASSERT_TRUE(lost.is_object());
    EXPECT_EQ(lost["status"], "lost");
    EXPECT_EQ(lost["reason"], "caught by a sentinel");
    EXPECT_EQ(lost["score"], 0);
    nlohmann::json again = play("lose_restart.input", 240, "restarted");
    ASSERT_TRUE(again.is_object());
    EXPECT_EQ(again["status"], "playing");
    EXPECT_EQ(again["restarts"], 1);
    EXPECT_EQ(again["score"], 10);
}

TEST(OrbGame, ReplaysAreDeterministic) {
    nlohmann::json a = play("win.input", 200, "det_a");
    nlohmann::json b = play("win.input", 200, "det_b");
    ASSERT_TRUE(a.is_object());
    EXPECT_EQ(a.dump(), b.dump());
}

TEST(OrbGame, BadInputAndBadLevelsAreRefusedClearly) {
    auto dir = tempDir();
    auto script = dir / "bad.input";
    std::ofstream(script) << "0 hold D\n";
    RunResult r = runGame("--headless --input " + script.string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find(script.string() + ":1: 'hold' takes a key and a frame count"),
              std::string::npos)
        << r.output;
    auto level = dir / "no_orb.scene.json";
    std::ofstream(level) << R"({"format": "candela.scene", "version": 1, "entities": [
        {"name": "rules", "gameData": {"role": "rules"}}]})";
    r = runGame("--headless " + level.string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("needs exactly one orb, found 0"), std::string::npos) << r.output;
    r = runGame("--headless /nonexistent/level.scene.json");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("/nonexistent/level.scene.json"), std::string::npos) << r.output;
}

// Issue 22: the game state on a full disk (or /dev/full) is a failure naming the path and
// the operating system's error, never a 0-byte file and exit 0.
TEST(OrbGame, StateAndStatsOnAFullDiskFailClearly) {
    std::vector<std::string> targets;
    if (std::filesystem::exists("/dev/full")) targets.push_back("/dev/full");
    CANDELA_SMALL_FILESYSTEM_OR_SKIP(disk);
    disk->fill();
    targets.push_back((disk->dir() / "state.json").string());
    for (const std::string& target : targets) {
        for (const char* option : {"--state", "--stats"}) {
            RunResult r = runGame("--headless --size 32x24 --frames 2 --input " + kReplays +
                                  "win.input " + option + " " + target);
            EXPECT_EQ(r.exitCode, 1) << option << " " << target << "\n" << r.output;
            EXPECT_NE(r.output.find(target + ": cannot write: No space left on device"),
                      std::string::npos)
                << r.output;
        }
    }
    EXPECT_FALSE(std::filesystem::exists(disk->dir() / "state.json"));
}
