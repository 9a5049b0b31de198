// The minimal game template (runtime/examples/minimal_game) replayed headless: the recorded
// input scores, no input scores nothing, replays repeat exactly, and the standard flags work.
// MINIMAL_GAME_EXECUTABLE in the environment tests another build of it (scripts/test: the
// template built outside the tree against the installed engine).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>

namespace {

struct RunResult {
    int exitCode = -1;
    std::string output;
};

RunResult runGame(const std::string& args) {
    const char* other = std::getenv("MINIMAL_GAME_EXECUTABLE");
    const std::string exe = other && *other ? other : MINIMAL_GAME_EXECUTABLE;
    const std::string command = exe + " " + args + " 2>&1";
    RunResult result;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return result;
    std::array<char, 4096> buffer{};
    while (size_t n = fread(buffer.data(), 1, buffer.size(), pipe))
        result.output.append(buffer.data(), n);
    const int status = pclose(pipe);
    if (WIFEXITED(status)) result.exitCode = WEXITSTATUS(status);
    return result;
}

const std::string kReplay = std::string(MINIMAL_GAME_DIR) + "/replays/collect.input";

// The score the game prints when the run ends ("score N after F frames"); -1 if absent.
int scoreOf(const RunResult& r, unsigned frames) {
    std::smatch m;
    const std::regex line("score (\\d+) after " + std::to_string(frames) + " frames");
    return std::regex_search(r.output, m, line) ? std::stoi(m[1]) : -1;
}

}  // namespace

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
