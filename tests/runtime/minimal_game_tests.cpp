// The minimal game template (runtime/examples/minimal_game) replayed headless: the recorded
// input scores, no input scores nothing, replays repeat exactly, and the standard flags work.
// MINIMAL_GAME_EXECUTABLE in the environment tests another build of it (scripts/test: the
// template built outside the tree against the installed engine).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "image_files.h"
#include "run_command.h"

namespace {

using candela::testing::runCommand;
using candela::testing::RunResult;

// MINIMAL_GAME_EXECUTABLE in the environment tests another build of the game (scripts/test runs
// these tests against the template built outside the tree on an installed engine).
RunResult runGame(const std::string& args) {
    const char* other = std::getenv("MINIMAL_GAME_EXECUTABLE");
    return runCommand(std::string(other && *other ? other : MINIMAL_GAME_EXECUTABLE) + " " + args);
}

const std::string kReplay = std::string(MINIMAL_GAME_DIR) + "/replays/collect.input";

// The score the game prints when the run ends ("score N after F frames"); -1 if absent.
// (Parsed by hand: std::regex trips GCC 12's maybe-uninitialized warning under ASan.)
int scoreOf(const RunResult& r, unsigned frames) {
    const std::string tail = " after " + std::to_string(frames) + " frames";
    const size_t end = r.output.find(tail);
    if (end == std::string::npos) return -1;
    const size_t start = r.output.rfind("score ", end);
    if (start == std::string::npos) return -1;
    const std::string digits = r.output.substr(start + 6, end - start - 6);
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) return -1;
    return std::stoi(digits);
}

// Pixels in [x0, x1) x [y0, y1) within `tolerance` levels of `rgb`.
int countNear(const candela::golden::LdrImage& image, int x0, int y0, int x1, int y1,
              std::array<int, 3> rgb, int tolerance) {
    int count = 0;
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            const std::uint8_t* p = &image.rgb[(std::size_t(y) * image.width + x) * 3];
            bool near = true;
            for (int c = 0; c < 3; ++c)
                near = near && std::abs(int(p[c]) - rgb[c]) <= tolerance;
            count += near;
        }
    }
    return count;
}

// The text region's pixels, to compare two captures' scores.
std::vector<std::uint8_t> region(const candela::golden::LdrImage& image, int x0, int y0, int x1,
                                 int y1) {
    std::vector<std::uint8_t> out;
    for (int y = y0; y < y1; ++y) {
        const std::uint8_t* row = &image.rgb[(std::size_t(y) * image.width + x0) * 3];
        out.insert(out.end(), row, row + (x1 - x0) * 3);
    }
    return out;
}

}  // namespace

// The score is drawn on screen, headless too, so a capture shows it: the template prints
// "SCORE N" at (16, 16), scale 2, in (1, 0.9, 0.3) with a black outline.
TEST(MinimalGame, TheScoreIsDrawnIntoCaptures) {
    const auto dir = std::filesystem::path(testing::TempDir()) / "candela_minimal_game";
    std::filesystem::create_directories(dir);
    const auto first = dir / "first.png", last = dir / "last.png";
    RunResult start = runGame("--headless --size 256x144 --frames 1 --capture " + first.string());
    ASSERT_EQ(start.exitCode, 0) << start.output;
    RunResult played = runGame("--headless --size 256x144 --frames 150 --input " + kReplay +
                               " --capture " + last.string());
    ASSERT_EQ(played.exitCode, 0) << played.output;
    ASSERT_GE(scoreOf(played, 150), 1) << played.output;
    std::string error;
    auto a = candela::golden::readLdrPng(first, error);
    ASSERT_TRUE(a) << error;
    auto b = candela::golden::readLdrPng(last, error);
    ASSERT_TRUE(b) << error;
    const std::array<int, 3> textColour{255, 230, 77};  // sRGB levels of (1, 0.9, 0.3)
    // "SCORE 0": 7 characters of 6 x 2 pixels, 14 pixels tall, plus the outline.
    const int x0 = 14, y0 = 14, x1 = 16 + 7 * 12 + 2, y1 = 16 + 14 + 2;
    EXPECT_GE(countNear(*a, x0, y0, x1, y1, textColour, 2), 100);
    EXPECT_GE(countNear(*a, x0, y0, x1, y1, {0, 0, 0}, 0), 100) << "the outline";
    EXPECT_EQ(countNear(*a, 0, 72, 256, 144, textColour, 2), 0) << "nothing else is text";
    // The digits follow the score: the two captures' text regions differ.
    EXPECT_NE(region(*a, x0, y0, x1, y1), region(*b, x0, y0, x1, y1));
    EXPECT_GE(countNear(*b, x0, y0, x1, y1, textColour, 2), 100);
}

TEST(MinimalGame, TheReplayScoresAndNoInputScoresNothing) {
    RunResult played = runGame("--headless --size 32x24 --frames 150 --input " + kReplay);
    ASSERT_EQ(played.exitCode, 0) << played.output;
    EXPECT_GE(scoreOf(played, 150), 3) << played.output;
    RunResult idle = runGame("--headless --size 32x24 --frames 150");
    ASSERT_EQ(idle.exitCode, 0) << idle.output;
    EXPECT_EQ(scoreOf(idle, 150), 0) << idle.output;
}

TEST(MinimalGame, ReplaysAreDeterministic) {
    RunResult a = runGame("--headless --size 32x24 --frames 120 --input " + kReplay);
    RunResult b = runGame("--headless --size 32x24 --frames 120 --input " + kReplay);
    ASSERT_EQ(a.exitCode, 0) << a.output;
    EXPECT_GE(scoreOf(a, 120), 1) << a.output;
    EXPECT_EQ(scoreOf(a, 120), scoreOf(b, 120));
}

// Issue 47: the template's one sound. Each touch chimes: as many chimes start in the captured
// mix as the game scores, and between them it is silent (the level has no other sound).
TEST(MinimalGame, EveryTouchChimes) {
    const std::filesystem::path wav =
        std::filesystem::temp_directory_path() / "candela-minimal-chimes.wav";
    RunResult r = runGame("--headless --size 32x24 --frames 150 --input " + kReplay +
                          " --audio-capture " + wav.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const int score = scoreOf(r, 150);
    ASSERT_GE(score, 1) << r.output;
    std::FILE* file = std::fopen(wav.c_str(), "rb");
    ASSERT_TRUE(file);
    std::vector<unsigned char> bytes(44 + 150 * 1600 * 4);
    const std::size_t read = std::fread(bytes.data(), 1, bytes.size() + 1, file);
    std::fclose(file);
    ASSERT_EQ(read, bytes.size());
    int onsets = 0;
    bool sounding = false;
    for (std::size_t frame = 0; frame < 150; ++frame) {
        double sum = 0;
        for (std::size_t i = 0; i < 2 * 1600; ++i) {
            const std::size_t at = 44 + 2 * (frame * 2 * 1600 + i);
            const double v = std::int16_t(bytes[at] | bytes[at + 1] << 8) / 32767.0;
            sum += v * v;
        }
        const bool loud = std::sqrt(sum / (2 * 1600)) > 0.05;  // a chime's first frames
        onsets += loud && !sounding;
        sounding = loud;
    }
    EXPECT_EQ(onsets, score);
}

// Issue 47: the template's one button. Two touches score 2; the replayed click on Reset (pressed
// at frame 100, released at 101) sets the score to 0 the frame after; before it, it is 2.
TEST(MinimalGame, TheResetButtonClearsTheScoreOnce) {
    const std::string replay = std::string(MINIMAL_GAME_DIR) + "/replays/reset.input";
    const RunResult before = runGame("--headless --size 320x180 --frames 102 --input " + replay);
    const RunResult after = runGame("--headless --size 320x180 --frames 104 --input " + replay);
    ASSERT_EQ(before.exitCode, 0) << before.output;
    ASSERT_EQ(after.exitCode, 0) << after.output;
    EXPECT_EQ(scoreOf(before, 102), 2) << before.output;
    EXPECT_EQ(scoreOf(after, 104), 0) << after.output;
}

TEST(MinimalGame, StandardFlagsAreCheckedAndListed) {
    RunResult bad = runGame("--frames zero");
    EXPECT_EQ(bad.exitCode, 2) << bad.output;
    EXPECT_NE(bad.output.find("minimal-game: --frames needs a positive integer, got 'zero'"),
              std::string::npos)
        << bad.output;
    RunResult unknown = runGame("--level x.json");
    EXPECT_EQ(unknown.exitCode, 2);
    EXPECT_NE(unknown.output.find("unknown option '--level'"), std::string::npos) << unknown.output;
    RunResult help = runGame("--help");
    EXPECT_EQ(help.exitCode, 0) << help.output;
    for (const char* flag : {"--headless", "--frames", "--size", "--input", "--capture", "--stats"})
        EXPECT_NE(help.output.find(flag), std::string::npos) << flag;
    RunResult missing = runGame("--headless --input /no/such/replay.input");
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_NE(missing.output.find("/no/such/replay.input"), std::string::npos) << missing.output;
}
