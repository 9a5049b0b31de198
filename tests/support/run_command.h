#pragma once
// Runs a command line through the shell for the command-line tests: its exit code and what it
// printed, stdout and stderr together.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace candela::testing {

struct RunResult {
    int exitCode = -1;   // -1 after a crash (a signal), so tests see a failure, not a code
    std::string output;  // stdout and stderr together
};

inline RunResult runCommand(const std::string& commandLine) {
    RunResult result;
    FILE* pipe = popen((commandLine + " 2>&1").c_str(), "r");
    if (!pipe) return result;
    std::array<char, 4096> buffer{};
    while (size_t n = fread(buffer.data(), 1, buffer.size(), pipe))
        result.output.append(buffer.data(), n);
    const int status = pclose(pipe);
    if (WIFEXITED(status)) result.exitCode = WEXITSTATUS(status);
    return result;
}

}  // namespace candela::testing
