#pragma once
// Command-line options of `candela run` and `candela demo`.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "candela/render/gpu_context.h"
#include "candela/render/renderer_options.h"

namespace candela::runtime {

struct RunOptions {
    std::string scene;  // engine scene file, .gltf, .glb, or a built-in "builtin:<name>"
    bool headless = false;
    uint32_t width = 1280;
    uint32_t height = 720;
    uint32_t frames = 0;                          // 0: until the window closes (headless: 1)
    std::vector<std::filesystem::path> captures;  // --capture may repeat (one .exr, one .png)
    std::optional<std::filesystem::path> stats;
    render::ValidationMode validation = render::ValidationMode::IfPresent;
    render::LightCulling lightCulling = render::LightCulling::Clustered;
    std::optional<double> stepSeconds;                 // --step: scene time per frame (fixed)
    std::optional<std::filesystem::path> captureEach;  // --capture-each DIR: DIR/frame_NN.png
    std::optional<std::filesystem::path> summary;      // --summary FILE.md
    render::LightAssignmentDevice lightAssignment = render::LightAssignmentDevice::Auto;
    std::optional<std::filesystem::path> frameGraph;   // --frame-graph FILE.dot
    std::optional<std::filesystem::path> inputScript;  // --input SCRIPT: recorded input
    std::optional<bool> overlay;  // --overlay / --no-overlay (default: demo in a window)
    std::optional<std::filesystem::path> environment;  // --env: overrides the scene's sky
    render::IblMode ibl = render::IblMode::SplitSum;
    std::optional<render::BrdfModel> brdf;  // --brdf; unset: the scene file's, else the default
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
