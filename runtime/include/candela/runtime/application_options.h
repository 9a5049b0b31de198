#pragma once
// What an Application run does: size, headless or windowed, frame count, captures, stats,
// recorded input and the renderer's choices. Kept apart from application.h so a game's
// option handling does not need the application loop.
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "candela/render/gpu_context.h"
#include "candela/render/renderer_options.h"
#include "candela/runtime/input_script.h"

namespace candela::runtime {

// Writes the frame rendered at `frame` (kLastFrame: the run's last) to `path` (.png or .exr).
struct FrameCapture {
    static constexpr std::uint32_t kLastFrame = std::numeric_limits<std::uint32_t>::max();
    std::uint32_t frame = kLastFrame;
    std::filesystem::path path;
};

struct ApplicationOptions {
    std::string title = "Candela";
    std::uint32_t width = 1280;
    std::uint32_t height = 720;
    bool headless = false;                 // also headless when no display is found
    std::uint32_t frames = 0;              // 0: until the window closes (headless: 1)
    double fixedStepSeconds = 1.0 / 30.0;  // scene time per frame when headless
    std::vector<FrameCapture> captures;
    std::optional<std::filesystem::path> stats;       // per-run JSON (see frame_stats.h)
    std::optional<std::filesystem::path> frameGraph;  // the last frame's graph as Graphviz
    bool countLightPairs = false;  // renderer counts light-pixel pairs (stats' culling figures)
    render::ValidationMode validation = render::ValidationMode::IfPresent;
    render::LightCulling lightCulling = render::LightCulling::Clustered;
    render::LightAssignmentDevice lightAssignment = render::LightAssignmentDevice::Auto;
    // The sky (image-based lighting and background): this file if set, else the world's Sky
    // component; a file that cannot be used gives a message and a neutral sky.
    std::optional<std::filesystem::path> environment;
    render::IblMode ibl = render::IblMode::SplitSum;
    // Replayed instead of window input; with it, windowed runs use the fixed step too.
    std::optional<InputScript> inputScript;
    bool captureCursor = false;  // window: hide the cursor and report raw motion (mouse look)
};

}  // namespace candela::runtime
