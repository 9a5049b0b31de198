#pragma once
// The application loop a game or tool drives: a world, systems that run every frame, input
// from a window (GLFW) or a recorded script, and rendering headless or to a window.
//
//   candela::runtime::ApplicationOptions options;
//   options.headless = true; options.frames = 60;
//   candela::runtime::Application app(options);
//   app.world().loadSceneFile("level.json", diagnostics);
//   app.addSystem("spin", [](SceneWorld& world, const FrameContext& frame) { ... });
//   return app.run();
//
// Each frame: input is gathered, systems run in the order they were added, transforms
// propagate, the ECS is extracted and the frame renders. Headless runs advance scene time by a
// fixed step, so the same options and input give the same frames, byte for byte.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "candela/render/frame_inputs.h"
#include "candela/render/gpu_context.h"
#include "candela/render/renderer_options.h"
#include "candela/runtime/frame_context.h"
#include "candela/runtime/frame_stats.h"
#include "candela/runtime/input_script.h"
#include "candela/runtime/input_state.h"
#include "candela/runtime/scene_world.h"

namespace candela::render {
class GpuContext;
class Renderer;
}  // namespace candela::render

namespace candela::runtime {

class Window;

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
    render::BrdfModel brdf = render::BrdfModel::EnergyConserving;
    // Replayed instead of window input; with it, windowed runs use the fixed step too.
    std::optional<InputScript> inputScript;
    bool captureCursor = false;  // window: hide the cursor and report raw motion (mouse look)
};

// Optional drawing on top of the frame (an ImGui overlay, debug lines). Called on the render
// thread with the device the application created.
class FrameLayer {
public:
    virtual ~FrameLayer() = default;
    // Once the device exists; `window` is null when headless.
    virtual void start(render::GpuContext& context, Window* window) = 0;
    // After the renderer recorded the frame (LDR target in TRANSFER_SRC_OPTIMAL), before the
    // capture copy and the blit to the window; `stats` are the previous frame's.
    virtual void record(VkCommandBuffer cmd, render::Renderer& renderer, const FrameContext& frame,
                        const FrameStats& stats) = 0;
    // Before the device is destroyed.
    virtual void stop() = 0;
};

using System = std::function<void(SceneWorld&, const FrameContext&)>;

class Application {
public:
    explicit Application(ApplicationOptions options);
    ~Application();
    Application(const Application&) = delete;
    Application& operator=(const Application&) = delete;

    SceneWorld& world() { return *world_; }
    bool hasWorld() const { return world_ != nullptr; }
    // Replaces the world; null draws only frameInputs() (background, test triangle).
    void setWorld(std::unique_ptr<SceneWorld> world);
    // Background radiance and other per-frame renderer inputs not read from the ECS.
    render::FrameInputs& frameInputs() { return frame_; }

    // Systems run every frame in the order added, before transforms propagate.
    void addSystem(std::string name, System system);
    void addLayer(std::shared_ptr<FrameLayer> layer);
    // Ends the run after the current frame (e.g. from a system).
    void requestQuit() { quitRequested_ = true; }
    // The window's title from the next frame on (a HUD line for small games); no-op headless.
    void setWindowTitle(std::string title) { windowTitle_ = std::move(title); }

    // Runs until the frame count, the window closing, a script's quit or requestQuit().
    // Returns an ExitCode (exit_code.h); errors are printed to stderr.
    int run();

    const ApplicationOptions& options() const { return options_; }
    const FrameStats& stats() const { return stats_; }
    const InputState& input() const { return input_; }
    std::uint32_t framesRendered() const { return std::uint32_t(stats_.frameMs.size()); }

private:
    struct Session;
    int runSession(bool headless, std::uint32_t frames);
    void updateSky(Session& session);

    ApplicationOptions options_;
    std::unique_ptr<SceneWorld> world_;
    render::FrameInputs frame_;
    std::vector<std::pair<std::string, System>> systems_;
    std::vector<std::shared_ptr<FrameLayer>> layers_;
    InputState input_;
    FrameStats stats_;
    bool quitRequested_ = false;
    std::string windowTitle_;
};

// CANDELA_VALIDATION=require|off|on (unset: on, i.e. IfPresent), as every test sets it.
render::ValidationMode validationModeFromEnvironment();

}  // namespace candela::runtime
