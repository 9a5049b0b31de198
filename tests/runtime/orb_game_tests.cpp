// candela-orb-game driven headless by recorded input, as its replays are meant to be used:
// the score after N frames, winning, losing, restarting, and bad input refused clearly.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>
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

nlohmann::json play(const std::string& replay, int frames, const std::string& name,
                    const std::string& extra = {}) {
    auto state = tempDir() / (name + ".json");
    std::filesystem::remove(state);
    RunResult r = runGame("--headless --size 32x24 --frames " + std::to_string(frames) +
                          " --input " + kReplays + replay + " --state " + state.string() + extra);
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

// Issue 47: the left stick steers as the keys do: the gamepad replay of win.input wins the same.
TEST(OrbGame, AGamepadReplayPlaysAsTheKeyboardReplay) {
    nlohmann::json keys = play("win.input", 400, "keys");
    nlohmann::json pad = play("win_gamepad.input", 400, "pad");
    ASSERT_TRUE(keys.is_object() && pad.is_object());
    EXPECT_EQ(pad["status"], "won");
    for (const char* field : {"status", "score", "collected", "elapsed_seconds"})
        EXPECT_EQ(pad[field], keys[field]) << field;
}

// A bindings file the player edited rebinds the controls; a bad one is named and the default
// controls stand.
TEST(OrbGame, ABindingsFileRebindsTheControlsAndABadOneIsNamed) {
    const auto dir = tempDir();
    std::ofstream(dir / "keys.json") << R"({"axes": {"steer_x": {"positive": ["key:L"]}}})";
    std::ofstream(dir / "east.input") << "0 hold L 95\n";
    std::ofstream(dir / "typo.json") << R"({"axes": {"steer_x": {"positive": ["key:Elle"]}}})";
    const auto state = dir / "l.json";
    RunResult r =
        runGame("--headless --size 32x24 --frames 95 --input " + (dir / "east.input").string() +
                " --state " + state.string() + " --bindings " + (dir / "keys.json").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(state);
    const nlohmann::json east = nlohmann::json::parse(in, nullptr, false);
    EXPECT_EQ(east["score"], 20) << "L steers east as D did: the two sparks on the south wall";
    const RunResult typo = runGame("--headless --size 32x24 --frames 95 --input " + kReplays +
                                   "win.input --bindings " + (dir / "typo.json").string());
    EXPECT_EQ(typo.exitCode, 0) << typo.output;
    EXPECT_NE(typo.output.find((dir / "typo.json").string() +
                               ": axes/steer_x/positive: 'key:Elle' is not a binding"),
              std::string::npos)
        << typo.output;
    EXPECT_NE(typo.output.find("the default controls stand"), std::string::npos) << typo.output;
}

TEST(OrbGame, TouchingASentinelLosesAndRRestarts) {
    nlohmann::json lost = play("lose_restart.input", 140, "lost");
    ASSERT_TRUE(lost.is_object());
    EXPECT_EQ(lost["status"], "lost");
    EXPECT_EQ(lost["reason"], "caught by a sentinel");
    EXPECT_EQ(lost["score"], 0);
    // The restart is checked by MascotAnimationFollowsTheGame, on the same replay's 240 frames
    // (one run serves both).
}

TEST(OrbGame, ReplaysAreDeterministic) {
    nlohmann::json a = play("win.input", 200, "det_a");
    nlohmann::json b = play("win.input", 200, "det_b");
    ASSERT_TRUE(a.is_object());
    EXPECT_EQ(a.dump(), b.dump());
}

// Issue 47: --record-input writes the run's input as a script; replaying the recording plays
// the same game (here the recorded run itself replays win_gamepad.input, stick and all).
TEST(OrbGame, ARecordedRunReplaysTheSameGame) {
    const std::filesystem::path recorded = tempDir() / "recorded.input";
    std::filesystem::remove(recorded);
    nlohmann::json original =
        play("win_gamepad.input", 200, "recording", " --record-input " + recorded.string());
    ASSERT_TRUE(std::filesystem::exists(recorded));
    auto state = tempDir() / "replayed.json";
    RunResult r = runGame("--headless --size 32x24 --frames 200 --input " + recorded.string() +
                          " --state " + state.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    nlohmann::json replayed = nlohmann::json::parse(std::ifstream(state), nullptr, false);
    ASSERT_TRUE(original.is_object() && replayed.is_object());
    EXPECT_GT(original["collected"].get<int>(), 0);
    EXPECT_EQ(replayed.dump(), original.dump());
}

// Issue 47: the title menu (--title) holds the clock until Play is pressed, by a replayed mouse
// click or by the gamepad on the focused button, and each press starts the game exactly once:
// the clock runs from the frame after the event (frame 5 for the click released at frame 4,
// frame 3 for A pressed at frame 2).
TEST(OrbGame, TheTitleMenusPlayButtonStartsTheGameByMouseOrGamepad) {
    const auto run = [](const std::string& replay, const std::string& name) {
        auto state = tempDir() / (name + ".json");
        std::filesystem::remove(state);
        RunResult r = runGame("--headless --title --size 320x180 --frames 30 --input " + kReplays +
                              replay + " --state " + state.string());
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return std::pair{r, nlohmann::json::parse(std::ifstream(state), nullptr, false)};
    };
    const auto [click, clicked] = run("title_click.input", "title_click");
    ASSERT_TRUE(clicked.is_object()) << click.output;
    EXPECT_EQ(clicked["status"], "playing");
    EXPECT_NEAR(clicked["elapsed_seconds"].get<double>(), 25.0 / 30.0, 1e-9);
    const auto [pad, padded] = run("title_gamepad.input", "title_pad");
    ASSERT_TRUE(padded.is_object()) << pad.output;
    EXPECT_NEAR(padded["elapsed_seconds"].get<double>(), 27.0 / 30.0, 1e-9);
    for (const RunResult* r : {&click, &pad}) {
        const std::size_t first = r->output.find("play\n");
        ASSERT_NE(first, std::string::npos) << r->output;
        EXPECT_EQ(r->output.find("play\n", first + 1), std::string::npos) << "fired once";
    }
    // Without a press the menu stays and the clock waits; replays without --title never see it.
    const auto [idle, waiting] = run("lose_restart.input", "title_idle");
    EXPECT_EQ(waiting["status"], "title");
    EXPECT_EQ(waiting["elapsed_seconds"], 0.0);
}

// Issue 47: the orb game's sounds. The replay mixes the same WAV bytes twice; the ambience
// loops under everything from the first frame, and each collected spark adds its chime (the
// two sparks win.input takes by frame 95 stand out of the ambience; the orb grazing a wall may
// thud).
TEST(OrbGame, AReplayMixesTheSameSoundTwice) {
    const auto capture = [](const std::string& name) {
        const std::filesystem::path wav = tempDir() / (name + ".wav");
        const std::filesystem::path stats = tempDir() / (name + ".stats.json");
        nlohmann::json s = play("win.input", 100, name,
                                " --audio-capture " + wav.string() + " --stats " + stats.string());
        EXPECT_EQ(s["collected"], 2) << s.dump();
        std::ifstream in(wav, std::ios::binary);
        return std::pair{std::string{std::istreambuf_iterator<char>(in), {}},
                         nlohmann::json::parse(std::ifstream(stats), nullptr, false)};
    };
    const auto [a, statsA] = capture("sound_a");
    const auto [b, statsB] = capture("sound_b");
    ASSERT_EQ(a.size(), 44u + 100u * 1600u * 4u);
    EXPECT_TRUE(a == b) << "the same replay must mix the same bytes";
    ASSERT_TRUE(statsA.contains("audio")) << statsA.dump();
    EXPECT_EQ(statsA["audio"]["voices_max"], 3);  // ambience, collect and hit
    // Loudness per frame (left + right): the ambience alone, then the chimes on top.
    std::vector<double> frameRms;
    for (std::size_t f = 0; f < 100; ++f) {
        double sum = 0;
        for (std::size_t i = 0; i < 2 * 1600; ++i) {
            const std::size_t at = 44 + 2 * (f * 2 * 1600 + i);
            const auto v = std::int16_t(std::uint16_t(std::uint8_t(a[at])) |
                                        std::uint16_t(std::uint8_t(a[at + 1])) << 8);
            sum += double(v) * v;
        }
        frameRms.push_back(std::sqrt(sum / (2 * 1600)) / 32767.0);
    }
    std::vector<double> sorted = frameRms;
    std::sort(sorted.begin(), sorted.end());
    const double ambience = sorted[sorted.size() / 2];
    EXPECT_GT(ambience, 0.01) << "the ambience plays from the start";
    // A sound starts where a frame is three times the ambience and the one before is not.
    int onsets = 0;
    for (std::size_t f = 1; f < frameRms.size(); ++f)
        onsets += frameRms[f] > 3.0 * ambience && frameRms[f - 1] <= 3.0 * ambience;
    EXPECT_GE(onsets, 2) << "the two chimes over the ambience";
    EXPECT_LE(onsets, 4) << "and at most a bump or two besides";
}

// The mascot (the shared Fox, --mascot; the game's test passes the shared asset's path) idles
// on Survey, crossfades to Walk over 0.25 s when
// the game is lost, back to Survey on the restart, and to Run when the player scores; clip
// times advance by the fixed 1/30 s step. Frames come from one replay, checked row by row.
TEST(OrbGame, MascotAnimationFollowsTheGame) {
    const std::string fox = std::string(CANDELA_SHARED_ASSETS) + "/models/Fox/Fox.glb";
    nlohmann::json s = play("lose_restart.input", 240, "restarted", " --mascot " + fox);
    ASSERT_TRUE(s.is_object() && s.contains("mascot")) << s.dump();
    // The game itself: lost, restarted with R, first spark collected (the mascot changes none).
    EXPECT_EQ(s["status"], "playing");
    EXPECT_EQ(s["restarts"], 1);
    EXPECT_EQ(s["score"], 10);
    const nlohmann::json& m = s["mascot"];
    const auto clipIndex = [&](const char* name) {
        for (std::size_t i = 0; i < m["clips"].size(); ++i)
            if (m["clips"][i]["name"] == name) return int(i);
        return -1;
    };
    const int survey = clipIndex("Survey"), walk = clipIndex("Walk"), run = clipIndex("Run");
    ASSERT_GE(survey, 0);
    ASSERT_EQ(m["idle"], survey);
    ASSERT_EQ(m["sulk"], walk);
    ASSERT_EQ(m["cheer"], run);
    const nlohmann::json& rows = m["frames"];
    ASSERT_EQ(rows.size(), 240u);
    constexpr float kStep = 1.0f / 30.0f, kFade = 0.25f;
    const auto clip = [&](int f) { return rows[f][1].get<int>(); };
    const auto time = [&](int f) { return rows[f][2].get<float>(); };
    const auto next = [&](int f) { return rows[f][3].get<int>(); };
    const auto weight = [&](int f) { return rows[f][4].get<float>(); };
    const auto status = [&](int f) { return rows[f][6].get<std::string>(); };
    const auto duration = [&](int c) { return m["clips"][c]["duration"].get<float>(); };
    // The frames where the game changed: lost, restarted, first spark.
    int lost = -1, restarted = -1, scored = -1;
    for (int f = 1; f < 240; ++f) {
        if (lost < 0 && status(f) == "lost") lost = f;
        if (lost >= 0 && restarted < 0 && status(f) == "playing") restarted = f;
        if (restarted >= 0 && scored < 0 && rows[f][5].get<int>() > 0) scored = f;
    }
    ASSERT_GT(lost, 10);
    ASSERT_GT(restarted, lost + 10);
    ASSERT_GT(scored, restarted + 10);
    ASSERT_LT(scored + 31, 240);
    for (int f = 0; f < lost; ++f) {
        ASSERT_EQ(clip(f), survey) << "frame " << f;
        ASSERT_EQ(next(f), -1) << "frame " << f;
        EXPECT_NEAR(time(f), std::fmod(static_cast<float>(f) * kStep, duration(survey)), 1e-4)
            << "frame " << f;
    }
    // The frame the game changes, the mascot asks for the crossfade (weight 0 until it runs).
    EXPECT_EQ(next(lost), walk);
    EXPECT_EQ(weight(lost), 0.0f);
    // Each reaction: the next frame blends one step of the 0.25 s fade, and the fade ends
    // after 8 steps (8/30 s > 0.25 s) with the new clip 8 steps in.
    for (auto [at, from, to] : {std::tuple{lost, survey, walk}, std::tuple{restarted, walk, survey},
                                std::tuple{scored, survey, run}}) {
        EXPECT_EQ(clip(at + 1), from) << "frame " << at + 1;
        EXPECT_EQ(next(at + 1), to) << "frame " << at + 1;
        EXPECT_NEAR(weight(at + 1), kStep / kFade, 1e-4) << "frame " << at + 1;
        EXPECT_NEAR(weight(at + 4), 4 * kStep / kFade, 1e-4) << "frame " << at + 4;
        EXPECT_EQ(clip(at + 8), to) << "frame " << at + 8;
        EXPECT_EQ(next(at + 8), -1) << "frame " << at + 8;
        EXPECT_NEAR(time(at + 8), 8 * kStep, 1e-4) << "frame " << at + 8;
    }
    // A second after the spark, the cheer blends back to idle.
    EXPECT_EQ(clip(scored + 30), run);
    EXPECT_EQ(next(scored + 30), survey);
    EXPECT_EQ(next(scored + 29), -1);
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
