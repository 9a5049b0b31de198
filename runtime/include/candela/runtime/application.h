#pragma once
// The application loop a game or tool drives: a world, systems that run every frame, input
// from a window (GLFW) or a recorded script, and rendering headless or to a window. The
// `candela` executable, games and the editor all run on it: one window, one frame loop.
//
//   candela::runtime::ApplicationOptions options;
//   options.headless = true; options.frames = 60;
//   candela::runtime::Application app(options);
//   app.world().loadSceneFile("level.json", diagnostics);
//   app.addSystem("spin", [](SceneWorld& world, const FrameContext& frame) { ... });
//   app.addSystem("patrol", ecs::Phase::Update, patrol).reads<Hazard>().writes<LocalTransform>();
//   return app.run();
//
// Each frame:
//   1. input is gathered (window events or the input script);
//   2. frame-start callbacks run (onFrameStart: tools switch scenes, request captures);
//   3. a world given to setWorld() during the run takes over;
//   4. the systems run on an ecs::Scheduler, phase by phase (system_declaration.h): those
//      whose declared read/write sets do not conflict in parallel, the rest in the order
//      added; transform propagation is the PostUpdate phase's first system;
//   5. the ECS is extracted for the renderer, then before-render callbacks may adjust what is
//      drawn (onBeforeRender: the editor's viewport camera);
//   6. layers prepare (FrameLayer::prepare), the frame graph records the scene, tonemapping
//      and one pass per layer, and the frame is captured, shown and submitted.
// Headless runs advance scene time by a fixed step, so the same options and input give the
// same frames, byte for byte. This header and those it includes need no Vulkan.
#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "candela/ecs/scheduler.h"
#include "candela/render/renderer_options.h"
#include "candela/runtime/application_options.h"
#include "candela/runtime/frame_context.h"
#include "candela/runtime/frame_layer.h"
#include "candela/runtime/frame_stats.h"
#include "candela/runtime/input_script.h"
#include "candela/runtime/input_state.h"
#include "candela/runtime/scene_world.h"
#include "candela/runtime/system_declaration.h"

namespace candela::render {
struct FrameInputs;
}  // namespace candela::render

namespace candela::runtime {

struct ExtractedFrame;

using System = std::function<void(SceneWorld&, const FrameContext&)>;
// Runs once per frame after input is gathered, before systems (scripts, scene switching).
using FrameCallback = std::function<void(const FrameContext&)>;
// Runs once per frame after extraction, before recording: `inputs` is what the renderer draws
// (camera, draws, lights, background) and may be changed; `extracted` is what the ECS gave.
using RenderCallback = std::function<void(
    render::FrameInputs& inputs, const ExtractedFrame& extracted, const FrameContext& frame)>;

class Application {
public:
    explicit Application(ApplicationOptions options);
    ~Application();
    Application(const Application&) = delete;
    Application& operator=(const Application&) = delete;

    SceneWorld& world();
    bool hasWorld() const;
    // Replaces the world; null draws only frameInputs() (background, test triangle). During a
    // run (from a callback or a system) the new world takes over at step 3 of the next frame
    // start, or of this one when called from onFrameStart; the old one lives until then.
    void setWorld(std::unique_ptr<SceneWorld> world);
    // Background radiance and other per-frame renderer inputs not read from the ECS
    // (render/frame_inputs.h).
    render::FrameInputs& frameInputs();
    // The radiance behind the scene where nothing is drawn, in cd/m^2 (RGBA).
    void setClearRadiance(const std::array<float, 4>& radiance);

    // An exclusive system (reads and writes everything, may change structure), in the Update
    // phase: systems added so run one at a time in the order added.
    void addSystem(std::string name, System system);
    // A system in `phase` that touches only what the returned declaration lists: it runs in
    // parallel with systems it does not conflict with (system_declaration.h).
    SystemDeclaration& addSystem(std::string name, ecs::Phase phase, System system);
    // The scheduler's plan, one stage per line ("Update: animate | hud" runs both at once).
    std::string describeSystems();
    // Runs the systems (and transform propagation) once for `frame`, without rendering: for
    // tests and tools. `frame.input` may be null (an empty input state is used).
    void update(const FrameContext& frame);

    void addLayer(std::shared_ptr<FrameLayer> layer);
    void onFrameStart(FrameCallback callback);
    void onBeforeRender(RenderCallback callback);
    // Captures the frame being made (called before it records: from onFrameStart, a system or
    // onBeforeRender) to `path` (.png: what the window shows; .exr: scene radiance).
    void captureFrame(std::filesystem::path path);
    // A cut for the frame being made (called before it records): temporal antialiasing,
    // motion vectors and exposure adaptation start afresh (Renderer::restartTemporalHistory).
    // A world handed over with setWorld gets one by itself.
    void restartTemporalHistory();
    // Ends the run after the current frame (e.g. from a system; safe from parallel systems).
    // The other calls that change the application (setWorld, captureFrame, addSystem) belong
    // in callbacks or exclusive systems, not in systems that run in parallel.
    void requestQuit();
    // The window's title from the next frame on (a HUD line for small games); no-op headless.
    void setWindowTitle(std::string title);

    // Runs until the frame count, the window closing, a script's quit or requestQuit().
    // Returns an ExitCode (exit_code.h); errors are printed to stderr.
    int run();

    const ApplicationOptions& options() const;
    const FrameStats& stats() const;
    const InputState& input() const;
    std::uint32_t framesRendered() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace candela::runtime
