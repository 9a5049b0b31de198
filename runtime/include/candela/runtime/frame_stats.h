#pragma once
// Per-run measurements written by --stats. Field names are a contract: add, never rename.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "candela/content/render_settings.h"
#include "candela/render/environment_stats.h"
#include "candela/render/renderer_options.h"

namespace candela::runtime {

struct FrameStats {
    uint32_t width = 0;
    uint32_t height = 0;
    std::string device;
    // The quality preset the run used and where it came from ("flag", "scene", "device").
    std::string quality;
    std::string qualitySource;
    // The render settings the run used (--stats "settings": each row's value under its stats
    // name, content/render_setting_table.h).
    content::RenderSettings settings;
    // The size the scene rendered at (RendererOptions::renderScale of width x height).
    uint32_t renderWidth = 0;
    uint32_t renderHeight = 0;
    std::vector<double> frameMs;  // CPU wall time per frame, including the wait for the GPU
    uint32_t validationMessages = 0;
    std::vector<std::string> features;
    std::vector<render::RendererStats> frames;  // one per rendered frame
    // Physics per frame, once the world has any (--stats "physics"): the time of its update
    // (Bullet's steps and the ECS integration) and what it held.
    struct PhysicsFrame {
        double simulateMs = 0;
        double integrationMs = 0;
        std::uint32_t steps = 0;
        std::uint32_t bodies = 0;
        std::uint32_t activeBodies = 0;
    };
    std::vector<PhysicsFrame> physics;
    // Audio per frame, once the run has a sound device (--stats "audio"): the time to sync the
    // sources and, on a loopback device, to mix the frame's samples.
    struct AudioFrame {
        double updateMs = 0;
        double mixMs = 0;
        std::uint32_t voices = 0;
        std::uint32_t playing = 0;
    };
    std::vector<AudioFrame> audio;
    std::optional<render::EnvironmentBuildStats> environment;  // when the scene has a sky

    void addRendererStats(const render::RendererStats& frame) { frames.push_back(frame); }
    double frameMsMedian() const;
};

// Lit light-pixel pairs over evaluated ones (1.0: every light the shader looked at reached
// the pixel); 0 when the renderer did not count pairs.
double cullingEfficiency(const render::RendererStats& frame);

// Returns an empty string on success, else a message naming the file.
std::string writeStatsJson(const std::filesystem::path& path, const FrameStats& stats);

}  // namespace candela::runtime
