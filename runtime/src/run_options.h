#pragma once
// Command-line options of `candela run` and `candela demo`: the standard flags every game gets
// (ApplicationOptions::fromCommandLine) plus the scene and the flags only `candela` has.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "candela/runtime/application_options.h"

namespace candela::runtime {

struct RunOptions {
    ApplicationOptions app;  // the standard flags (--capture gives last-frame captures)
    std::string scene;       // engine scene file, .gltf, .glb, or a built-in "builtin:<name>"
    std::optional<std::filesystem::path> captureEach;  // --capture-each DIR: DIR/frame_NN.png
    std::optional<std::filesystem::path> summary;      // --summary FILE.md
    std::optional<std::string> animation;  // --animation NAME|INDEX (default: the first clip)
    std::optional<bool> overlay;  // --overlay / --no-overlay (default: demo in a window)
};

struct ParseResult {
    std::optional<RunOptions> options;
    std::string error;  // set when options is empty and the arguments were wrong
    bool helpRequested = false;
};

// args excludes the program name and the subcommand.
ParseResult parseRunOptions(const std::vector<std::string>& args);
std::string runUsage();

}  // namespace candela::runtime
