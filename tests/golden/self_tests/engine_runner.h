#pragma once
// Runs the real candela executable (and candela-golden) from the self tests, so perturbation
// tests capture frames exactly as golden tests do.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

namespace candela::golden::test {

struct CommandResult {
    int exitCode = -1;
    std::string output;  // stdout and stderr together
};

inline std::string quoted(const std::string& text) {
    std::string result = "'";
    for (char c : text)
        result += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return result + "'";
}

inline CommandResult runCommand(const std::string& command, const std::filesystem::path& log) {
    const int status = std::system((command + " > " + quoted(log.string()) + " 2>&1").c_str());
    CommandResult result;
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream in(log);
    result.output.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return result;
}

// A fresh directory per test and process, so tests of several build trees can run at once.
inline std::filesystem::path testDirectory() {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    auto dir = std::filesystem::path(testing::TempDir()) / "candela_golden" /
               (std::string(info->test_suite_name()) + "." + info->name() + "." +
                std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

// Kept when the test failed, so its images can be looked at.
inline void removeIfPassed(const std::filesystem::path& dir) {
    if (!testing::Test::HasFailure()) std::filesystem::remove_all(dir);
}

// Renders `scene` like a golden test does: <dir>/<name>.exr and <dir>/<name>.png.
inline CommandResult renderCapture(const std::string& scene, const std::string& size, int frames,
                                   const std::filesystem::path& dir, const std::string& name) {
    const std::string base = (dir / name).string();
    return runCommand(std::string(quoted(CANDELA_EXECUTABLE)) + " run " + quoted(scene) +
                          " --headless --size " + size + " --frames " + std::to_string(frames) +
                          " --capture " + quoted(base + ".exr") + " --capture " +
                          quoted(base + ".png"),
                      dir / (name + ".render.log"));
}

inline CommandResult runGoldenTool(const std::string& arguments, const std::filesystem::path& log) {
    return runCommand(std::string(quoted(CANDELA_GOLDEN_EXECUTABLE)) + " " + arguments, log);
}

}  // namespace candela::golden::test
