#include "candela/runtime/application.h"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <mutex>

#include "candela/content/animation_systems.h"
#include "candela/content/atomic_file_write.h"
#include "candela/ecs/transform_system.h"
#include "candela/render/frame_capture.h"
#include "candela/render/frame_inputs.h"
#include "candela/render/frame_submitter.h"
#include "candela/render/gpu_context.h"
#include "candela/render/renderer.h"
#include "candela/render/scene_resources.h"
#include "candela/render/swapchain.h"
#include "candela/runtime/atmosphere_sun.h"
#include "candela/runtime/exit_code.h"
#include "candela/runtime/frame_extraction.h"
#include "candela/runtime/input_recorder.h"
#include "candela/runtime/layer_pass_context.h"
#include "candela/runtime/light_table.h"
#include "candela/runtime/sky_loader.h"
#include "candela/runtime/window.h"
#include "frame_settings.h"
#include "game_audio.h"
#include "physics_debug_view.h"
#include "window_surface.h"

namespace candela::runtime {

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Checked before rendering so a bad path fails in milliseconds, not after the frames.
std::string checkWritable(const std::filesystem::path& path) {
    std::filesystem::path dir = path.parent_path();
    if (dir.empty()) dir = ".";
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec)) {
        return path.string() + ": directory '" + dir.string() + "' does not exist";
    }
    if (::access(dir.c_str(), W_OK) != 0) {
        return path.string() + ": directory '" + dir.string() + "' is not writable";
    }
    if (std::filesystem::is_directory(path, ec)) return path.string() + ": is a directory";
    return {};
}

bool displayAvailable() {
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (display && *display) || (wayland && *wayland);
}

}  // namespace

render::ValidationMode validationModeFromEnvironment() {
    const char* value = std::getenv("CANDELA_VALIDATION");
    if (!value) return render::ValidationMode::IfPresent;
    std::string mode = value;
    if (mode == "require") return render::ValidationMode::Required;
    if (mode == "off") return render::ValidationMode::Off;
    return render::ValidationMode::IfPresent;
}

const render::GpuImage& LayerPassContext::image(render::FrameTarget target) const {
    return target == render::FrameTarget::Hdr ? renderer_.hdrTarget() : renderer_.ldrTarget();
}

std::uint32_t LayerPassContext::width() const {
    return renderer_.width();
}

std::uint32_t LayerPassContext::height() const {
    return renderer_.height();
}

namespace {

// What exists only while run() runs: the device, the renderer and what they hold.
struct Session {
    std::unique_ptr<render::GpuContext> context;
    std::unique_ptr<render::Renderer> renderer;
    std::unique_ptr<render::FrameSubmitter> submitter;
    std::unique_ptr<render::SceneResources> resources;
    std::unique_ptr<LightTable> lightTable;
    std::unique_ptr<render::FrameReadback> readback;
    std::uint32_t readbackWidth = 0, readbackHeight = 0;
    std::unique_ptr<Window> window;
    ExtractedFrame extracted;
    // Captures wanted per frame index (kLastFrame resolved to the run's last frame).
    std::map<std::uint32_t, std::vector<std::filesystem::path>> captures;
    std::vector<std::filesystem::path> capturesMissed;
    int exitCode = kExitOk;
    SkyLoader sky;
    AtmosphereSun sun;              // the atmosphere's sun among the frame's lights
    PhysicsDebugView physicsDebug;  // --physics-debug's wires
    std::unique_ptr<GameAudio> audio;
    std::unique_ptr<InputRecorder> recorder;  // --record-input
};

struct SystemEntry {
    std::string name;
    ecs::Phase phase;
    System fn;
    SystemDeclaration declaration;
};

}  // namespace

struct Application::Impl {
    ApplicationOptions options;
    std::unique_ptr<SceneWorld> world;
    std::unique_ptr<SceneWorld> pendingWorld;
    bool worldPending = false;
    render::FrameInputs frame;
    // Stable addresses: addSystem hands out references to the declarations.
    std::vector<std::unique_ptr<SystemEntry>> systems;
    ecs::JobSystem jobs;
    std::unique_ptr<ecs::Scheduler> scheduler;  // on world's registry; rebuilt when stale
    bool schedulerStale = true;
    FrameContext current;  // what systems get this frame
    std::vector<std::shared_ptr<FrameLayer>> layers;
    std::vector<FrameCallback> frameStart;
    std::vector<RenderCallback> beforeRender;
    std::vector<std::filesystem::path> capturesNow;  // captureFrame() for the current frame
    InputState input;
    FrameStats stats;
    std::atomic<bool> quitRequested = false;
    std::mutex titleMutex;
    std::string windowTitle;
    Session* session = nullptr;  // while running

    explicit Impl(ApplicationOptions o)
        : options(std::move(o)), world(std::make_unique<SceneWorld>()) {}

    void rebuildScheduler();
    void runSystems(const FrameContext& context);
    void swapWorld();
    void updateSky(Session& session);
    int runSession(bool headless, std::uint32_t frames);
};

// The scheduler is bound to one registry: made again for a new world, replaying the systems'
// declarations. Transform propagation (SceneWorld::updateTransforms: missing WorldTransforms
// added, unmarked changes caught, then propagation) is exclusive, so it may add components and
// sort the transform pools into propagation order, as it always has.
void Application::Impl::rebuildScheduler() {
    scheduler.reset();
    schedulerStale = false;
    if (!world) return;
    scheduler = std::make_unique<ecs::Scheduler>(world->registry, jobs);
    // Physics steps after the game's Update systems wrote kinematic targets and velocities,
    // and before propagation carries the bodies' new poses to their children.
    scheduler
        ->addSystem("physics", ecs::Phase::PostUpdate,
                    [this](ecs::SystemContext&) { world->stepPhysics(current.deltaSeconds); })
        .exclusive();
    scheduler
        ->addSystem("propagate transforms", ecs::Phase::PostUpdate,
                    [this](ecs::SystemContext&) { world->updateTransforms(); })
        .reads<ecs::LocalTransform, ecs::HierarchyNode>()
        .writes<ecs::WorldTransform>()
        .exclusive();
    // Clips are sampled in Update, before the game's own systems (which may override a pose);
    // joint matrices are rebuilt in PostUpdate after propagation. A world without animation
    // does not get these systems at all (the plan is rebuilt every frame, so animated
    // entities added later get them from the next frame on).
    if (!world->registry.view<content::AnimationPlayer>().empty() ||
        !world->registry.view<content::Skin>().empty()) {
        content::addAnimationSystems(*scheduler,
                                     [this] { return static_cast<float>(current.deltaSeconds); });
    }
    for (const auto& entry : systems) {
        const System* fn = &entry->fn;
        auto builder = scheduler->addSystem(
            entry->name, entry->phase, [this, fn](ecs::SystemContext&) { (*fn)(*world, current); });
        entry->declaration.applyTo(builder);
    }
}

void Application::Impl::runSystems(const FrameContext& context) {
    if (!world) return;
    if (schedulerStale) rebuildScheduler();
    current = context;
    scheduler->run();
}

// A world handed over during the run replaces the old one between frames: the GPU is idle
// (every frame waits for its submission), and what referred to the old registry goes first.
void Application::Impl::swapWorld() {
    if (!worldPending) return;
    worldPending = false;
    Session& s = *session;
    s.submitter->waitIdle();
    s.lightTable.reset();  // unhooks from the old registry before it goes
    s.extracted = {};
    s.renderer->restartTemporalHistory();  // nothing of the old world's frames carries over
    s.sky = SkyLoader(options.environment);
    s.resources = std::make_unique<render::SceneResources>(*s.context);
    s.audio->clear();  // the old world's sounds stop with it
    scheduler.reset();
    world = std::move(pendingWorld);
    schedulerStale = true;
}

// Loads the sky when the file named by the options or the world's Sky component changes
// (cached precomputation makes a reload of a known sky cheap).
void Application::Impl::updateSky(Session& s) {
    if (!s.sky.update(*world, s.extracted, *s.context, *s.submitter, *s.resources, "candela")) {
        return;
    }
    if (s.resources->environment()) {
        stats.environment = s.resources->environment()->stats();
    } else {
        stats.environment.reset();
    }
}

Application::Application(ApplicationOptions options)
    : impl_(std::make_unique<Impl>(std::move(options))) {}

Application::~Application() = default;

SceneWorld& Application::world() {
    return *impl_->world;
}

bool Application::hasWorld() const {
    return impl_->world != nullptr;
}

void Application::setWorld(std::unique_ptr<SceneWorld> world) {
    if (impl_->session) {
        impl_->pendingWorld = std::move(world);
        impl_->worldPending = true;
        return;
    }
    impl_->scheduler.reset();
    impl_->world = std::move(world);
    impl_->schedulerStale = true;
}

render::FrameInputs& Application::frameInputs() {
    return impl_->frame;
}

void Application::setClearRadiance(const std::array<float, 4>& radiance) {
    impl_->frame.clearRadiance = radiance;
}

void Application::addSystem(std::string name, System system) {
    addSystem(std::move(name), ecs::Phase::Update, std::move(system)).exclusive();
}

SystemDeclaration& Application::addSystem(std::string name, ecs::Phase phase, System system) {
    impl_->systems.push_back(std::make_unique<SystemEntry>(
        SystemEntry{std::move(name), phase, std::move(system), SystemDeclaration{}}));
    impl_->schedulerStale = true;
    return impl_->systems.back()->declaration;
}

std::string Application::describeSystems() {
    // Declarations made after addSystem returned count too: always plan afresh.
    impl_->rebuildScheduler();
    return impl_->scheduler ? impl_->scheduler->describe() : std::string();
}

void Application::update(const FrameContext& frame) {
    FrameContext context = frame;
    InputState none;
    if (!context.input) context.input = &none;
    impl_->schedulerStale = true;  // declarations may have grown since the last plan
    impl_->runSystems(context);
}

void Application::addLayer(std::shared_ptr<FrameLayer> layer) {
    impl_->layers.push_back(std::move(layer));
}

void Application::onFrameStart(FrameCallback callback) {
    impl_->frameStart.push_back(std::move(callback));
}

void Application::onBeforeRender(RenderCallback callback) {
    impl_->beforeRender.push_back(std::move(callback));
}

void Application::captureFrame(std::filesystem::path path) {
    impl_->capturesNow.push_back(std::move(path));
}

void Application::restartTemporalHistory() {
    if (impl_->session && impl_->session->renderer)
        impl_->session->renderer->restartTemporalHistory();
}

void Application::requestQuit() {
    impl_->quitRequested = true;
}

void Application::setWindowTitle(std::string title) {
    const std::lock_guard lock(impl_->titleMutex);
    impl_->windowTitle = std::move(title);
}

const ApplicationOptions& Application::options() const {
    return impl_->options;
}

const FrameStats& Application::stats() const {
    return impl_->stats;
}

const InputState& Application::input() const {
    return impl_->input;
}

std::uint32_t Application::framesRendered() const {
    return std::uint32_t(impl_->stats.frameMs.size());
}

int Application::run() {
    const ApplicationOptions& options = impl_->options;
    std::vector<std::filesystem::path> outputs;
    for (const FrameCapture& c : options.captures) {
        std::string ext = c.path.extension().string();
        if (ext != ".png" && ext != ".exr") {
            std::fprintf(stderr, "candela: %s: captures must end in .png or .exr\n",
                         c.path.c_str());
            return kExitBadArguments;
        }
        outputs.push_back(c.path);
    }
    if (options.stats) outputs.push_back(*options.stats);
    if (options.frameGraph) outputs.push_back(*options.frameGraph);
    for (const std::filesystem::path& path : outputs) {
        if (std::string e = checkWritable(path); !e.empty()) {
            std::fprintf(stderr, "candela: %s\n", e.c_str());
            return kExitBadArguments;
        }
    }
    bool headless = options.headless || !displayAvailable();
    if (!options.headless && headless) {
        std::fprintf(stderr, "candela: no display found, rendering headless\n");
    }
    std::uint32_t frames = options.frames != 0 ? options.frames : (headless ? 1 : 0);
    return impl_->runSession(headless, frames);
}

namespace {

// The layers' passes for this frame (layers with no uses add none).
std::vector<render::ExtraPass> layerPasses(const std::vector<std::shared_ptr<FrameLayer>>& layers,
                                           const render::Renderer& renderer) {
    std::vector<render::ExtraPass> passes;
    for (const auto& layer : layers) {
        std::vector<render::TargetAccess> uses = layer->uses();
        if (uses.empty()) continue;
        FrameLayer* raw = layer.get();
        const render::Renderer* r = &renderer;
        passes.push_back({layer->name(), std::move(uses), [raw, r](VkCommandBuffer cmd) {
                              LayerPassContext pass(cmd, *r);
                              raw->record(pass);
                          }});
    }
    return passes;
}

}  // namespace

int Application::Impl::runSession(bool headless, std::uint32_t frames) {
    stats = FrameStats{};
    stats.width = options.width;
    stats.height = options.height;
    input = InputState{};
    quitRequested = false;
    Session s;
    session = &s;
    struct EndOfSession {  // session points at `s` only while it exists
        Impl& impl;
        Session& s;
        ~EndOfSession() {
            impl.session = nullptr;
            if (impl.worldPending) {   // handed over during the last frame: take it now
                s.lightTable.reset();  // unhooks from the old registry before it goes
                impl.worldPending = false;
                impl.scheduler.reset();
                impl.world = std::move(impl.pendingWorld);
                impl.schedulerStale = true;
            }
        }
    } endOfSession{*this, s};
    s.sky = SkyLoader(options.environment);
    std::string frameGraphDot;
    for (const FrameCapture& c : options.captures) {
        if (c.frame == FrameCapture::kLastFrame && frames == 0) {
            s.capturesMissed.push_back(c.path);  // an open-ended window has no last frame
            continue;
        }
        std::uint32_t at = c.frame == FrameCapture::kLastFrame ? frames - 1 : c.frame;
        if (frames != 0 && at >= frames) {
            std::fprintf(stderr, "candela: %s: capture frame %u is past the run's %u frames\n",
                         c.path.c_str(), at, frames);
            return kExitBadArguments;
        }
        s.captures[at].push_back(c.path);
    }
    // Without captures asked for up front the render follows the window's size.
    const bool fixedRenderSize = !s.captures.empty();
    // A script (or a headless or recorded run) uses the fixed step, so its frames repeat exactly.
    const bool fixedStep =
        headless || options.inputScript.has_value() || options.recordInput.has_value();
    if (options.recordInput) s.recorder = std::make_unique<InputRecorder>();
    s.audio = std::make_unique<GameAudio>(headless, options.audioCapture);
    try {
        render::GpuContextOptions gpuOptions;
        gpuOptions.validation = options.validation;
        if (const char* preferred = std::getenv("CANDELA_DEVICE")) {
            gpuOptions.preferredDevice = preferred;
        }
        if (!headless) {
            gpuOptions.instanceExtensions = Window::requiredInstanceExtensions();
            gpuOptions.swapchain = true;
            s.window = std::make_unique<Window>(options.width, options.height, options.title);
            if (!options.inputScript) s.window->setInputTarget(&input);
            if (options.captureCursor) s.window->setCursorCaptured(true);
        }
        s.context = std::make_unique<render::GpuContext>(gpuOptions);
        if (std::string problem =
                render::Renderer::outputSizeProblem(*s.context, options.width, options.height);
            !problem.empty()) {
            std::fprintf(stderr, "candela: --size %ux%u: %s; choose a smaller size\n",
                         options.width, options.height, problem.c_str());
            return kExitBadArguments;
        }
        const QualityChoice quality =
            qualityFor(options, world.get(),
                       s.context->properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU);
        stats.quality = content::qualityLevelName(quality.level);
        stats.qualitySource = content::qualitySourceName(quality.source);
        render::RendererOptions rendererOptions = rendererOptionsFor(options, world.get(), quality);
        stats.settings = rendererOptions;
        // A headless run or one that writes stats is checked for non-finite radiance.
        rendererOptions.checkNonFinite = headless || options.stats.has_value();
        s.renderer = std::make_unique<render::Renderer>(*s.context, options.width, options.height,
                                                        rendererOptions);
        s.submitter = std::make_unique<render::FrameSubmitter>(*s.context);
        s.resources = std::make_unique<render::SceneResources>(*s.context);
        stats.device = s.context->deviceName();
        stats.renderWidth = s.renderer->renderWidth();
        stats.renderHeight = s.renderer->renderHeight();
        for (auto& layer : layers)
            layer->start(*s.context, s.window.get());

        VkSurfaceKHR surface = VK_NULL_HANDLE;
        std::unique_ptr<render::Swapchain> swapchain;
        if (s.window) {
            surface = createWindowSurface(*s.window, s.context->instance());
            swapchain = std::make_unique<render::Swapchain>(*s.context, surface, options.width,
                                                            options.height);
        }
        const Clock::time_point runStart = Clock::now();
        double previousSeconds = 0.0;
        // --stats-work last: a run of known length counts its last frame only.
        const bool countLightPairs = rendererOptions.countLightPairs;
        const bool countLastOnly = options.countWorkOnLastFrame && frames != 0;
        // A frame with non-finite radiance is followed by one that finds the pass it came
        // from; a run whose last frame had it renders that one more.
        std::uint32_t diagnosisFrames = 0;
        bool nonFiniteReported = false;
        for (std::uint32_t i = 0; frames == 0 || i < frames + diagnosisFrames; ++i) {
            Clock::time_point start = Clock::now();
            s.renderer->setCountLightPairs(countLightPairs && (!countLastOnly || i + 1 == frames));
            input.beginFrame();
            if (s.window) s.window->pollEvents();
            if (options.inputScript) options.inputScript->apply(i, input);
            const bool closing =
                input.closeRequested || quitRequested || (s.window && s.window->shouldClose());
            if (s.recorder) closing ? s.recorder->recordQuit(i) : s.recorder->record(i, input);
            if (closing) break;
            if (s.window) {
                const std::lock_guard lock(titleMutex);
                if (!windowTitle.empty()) {
                    s.window->setTitle(windowTitle);
                    windowTitle.clear();
                }
            }

            uint32_t imageIndex = 0;
            if (s.window) {
                if (s.window->consumeResized()) {
                    uint32_t w, h;
                    s.window->framebufferSize(w, h);
                    s.submitter->waitIdle();
                    swapchain->recreate(w, h);
                    if (!fixedRenderSize) s.renderer->resize(w, h);
                }
                s.submitter->waitIdle();
                if (!swapchain->acquire(s.submitter->imageAvailable(), imageIndex)) {
                    uint32_t w, h;
                    s.window->framebufferSize(w, h);
                    swapchain->recreate(w, h);
                    --i;  // the frame did not happen; its index is reused
                    continue;
                }
            }

            FrameContext frameContext;
            frameContext.frame = i;
            frameContext.seconds =
                fixedStep ? double(i) * options.fixedStepSeconds
                          : std::chrono::duration<double>(Clock::now() - runStart).count();
            frameContext.deltaSeconds = fixedStep ? (i == 0 ? 0.0 : options.fixedStepSeconds)
                                                  : frameContext.seconds - previousSeconds;
            previousSeconds = frameContext.seconds;
            frameContext.input = &input;
            frameContext.headless = headless;
            frameContext.width = s.renderer->width();
            frameContext.height = s.renderer->height();

            for (auto& callback : frameStart)
                callback(frameContext);
            swapWorld();

            render::SceneResources* resources = nullptr;
            if (world) {
                runSystems(frameContext);
                s.audio->update(*world, frameContext, fixedStep ? options.fixedStepSeconds : 0.0,
                                stats);
                float aspect = float(s.renderer->width()) / float(s.renderer->height());
                if (!s.lightTable) s.lightTable = std::make_unique<LightTable>(world->registry);
                extractFrame(world->registry, *s.lightTable, *s.resources, aspect, s.extracted);
                if (options.physicsDebug && world->hasPhysics()) {
                    s.physicsDebug.appendTo(world->physics(), s.extracted.camera.ev100,
                                            s.extracted.wires);
                }
                frame.scene.camera = s.extracted.camera;
                frame.scene.draws = s.extracted.draws;
                frame.scene.wires = s.extracted.wires;
                frame.scene.hair = s.extracted.hair;
                frame.scene.previousWorlds = s.extracted.previousWorlds;
                frame.scene.deforms = s.extracted.deforms;
                frame.scene.jointMatrices = s.extracted.jointMatrices;
                frame.scene.morphWeights = s.extracted.morphWeights;
                frame.deltaSeconds = float(frameContext.deltaSeconds);
                frame.scene.lights = s.extracted.lights;
                frame.scene.changedLights = s.extracted.changedLights;
                frame.scene.lightsRestructured = s.extracted.lightsRestructured;
                frame.scene.skyIntensity = s.extracted.skyIntensity;
                frame.scene.fog = options.fog ? options.fog : s.extracted.fog;
                if (const auto& ao = world->sceneAmbientOcclusion()) {
                    frame.scene.aoRadius = ao->radius;
                    frame.scene.aoIntensity = ao->intensity;
                }
                frame.text = std::move(s.extracted.text);
                // An atmosphere (the scene's, or Earth's for --atmosphere and the sun flags)
                // replaces the EXR sky and makes the first directional light its sun.
                frame.scene.atmosphere = s.extracted.atmosphere;
                if (options.atmosphereOff) frame.scene.atmosphere.reset();
                if (!frame.scene.atmosphere && !options.atmosphereOff &&
                    (options.atmosphere || options.sunElevationDegrees || options.timeOfDayHours)) {
                    frame.scene.atmosphere = content::Atmosphere{};
                }
                // Unchosen, sky occlusion follows the atmosphere: --stats says what ran.
                if (s.renderer->options().skyOcclusionWithAtmosphere) {
                    stats.settings.skyOcclusion = frame.scene.atmosphere
                                                      ? content::SkyOcclusionMode::On
                                                      : content::SkyOcclusionMode::Off;
                }
                if (frame.scene.atmosphere) {
                    frame.scene.skyIntensity = 1.0f;  // the sky is physical, in cd/m^2
                    s.sun.apply({options.sunElevationDegrees, options.timeOfDayHours}, frame.scene);
                } else {
                    updateSky(s);
                }
                resources = s.resources.get();
            }
            for (auto& callback : beforeRender)
                callback(frame, s.extracted, frameContext);
            for (auto& layer : layers)
                layer->prepare(frameContext, stats);

            const std::vector<render::ExtraPass> passes = layerPasses(layers, *s.renderer);
            VkCommandBuffer cmd = s.renderer->recordFrame(*s.submitter, frame, resources, passes);
            std::vector<std::filesystem::path> wanted = std::move(capturesNow);
            capturesNow.clear();
            if (auto at = s.captures.find(i); at != s.captures.end()) {
                wanted.insert(wanted.end(), at->second.begin(), at->second.end());
                s.captures.erase(at);
            }
            if (!wanted.empty()) {
                if (!s.readback || s.readbackWidth != s.renderer->width() ||
                    s.readbackHeight != s.renderer->height()) {
                    s.readbackWidth = s.renderer->width();
                    s.readbackHeight = s.renderer->height();
                    s.readback = std::make_unique<render::FrameReadback>(
                        *s.context, s.readbackWidth, s.readbackHeight);
                }
                s.readback->recordCopy(cmd, *s.renderer);
            }
            if (s.window) {
                swapchain->recordBlit(cmd, s.renderer->ldrTarget(), imageIndex);
                s.submitter->submit(s.submitter->imageAvailable(),
                                    swapchain->renderFinished(imageIndex));
                if (!swapchain->present(imageIndex)) {
                    uint32_t w, h;
                    s.window->framebufferSize(w, h);
                    s.submitter->waitIdle();
                    swapchain->recreate(w, h);
                }
            } else {
                s.submitter->submit();
            }
            s.submitter->waitIdle();
            stats.frameMs.push_back(millisecondsSince(start));
            if (world && world->hasPhysics()) {
                const physics::PhysicsTimings t = world->physics().lastTimings();
                const physics::PhysicsCounts c = world->physics().counts();
                stats.physics.push_back(
                    {1e3 * t.simulate, 1e3 * t.integration, t.steps, c.bodies, c.activeBodies});
            }
            const render::RendererStats& frameStats = s.renderer->collectStats();
            stats.addRendererStats(frameStats);
            if (frameStats.nonFinitePixels > 0 && !nonFiniteReported) {
                std::fprintf(stderr,
                             "candela: error: frame %u: %llu pixels of the scene's radiance are "
                             "not finite (NaN or Inf)\n",
                             i, static_cast<unsigned long long>(frameStats.nonFinitePixels));
                s.exitCode = kExitFailure;
                nonFiniteReported = true;
                s.renderer->diagnoseNonFiniteNextFrame();
                if (frames != 0 && i + 1 == frames) diagnosisFrames = 1;
            }
            if (!frameStats.nonFiniteSource.empty()) {
                std::fprintf(stderr,
                             "candela: error: frame %u: the first to write NaN or Inf: %s\n", i,
                             frameStats.nonFiniteSource.c_str());
            }
            if (!wanted.empty()) {
                render::CapturedFrame captured = s.readback->read();
                if (size_t bad = captured.nonFiniteHdrValues()) {
                    std::fprintf(stderr, "candela: warning: capture holds %zu NaN/Inf values\n",
                                 bad);
                }
                for (const std::filesystem::path& path : wanted) {
                    if (std::string e = render::writeCapture(path, captured); !e.empty()) {
                        std::fprintf(stderr, "candela: %s\n", e.c_str());
                        s.exitCode = kExitFailure;
                    } else {
                        std::printf("captured %s\n", path.c_str());
                    }
                }
            }
        }
        s.submitter->waitIdle();
        for (auto& layer : layers)
            layer->stop();
        swapchain.reset();
        if (surface != VK_NULL_HANDLE) vkDestroySurfaceKHR(s.context->instance(), surface, nullptr);
        if (s.window) s.window->setInputTarget(nullptr);
        stats.features = s.renderer->features();
        if (options.frameGraph) frameGraphDot = s.renderer->frameGraphDot();
        stats.validationMessages = s.context->validationMessages();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "candela: %s\n", e.what());
        // Layers hold device objects: they go before the device does.
        if (s.submitter) {
            for (auto& layer : layers) {
                try {
                    s.submitter->waitIdle();
                    layer->stop();
                } catch (const std::exception&) {
                }
            }
        }
        return kExitFailure;
    }
    // Frames the run ended before (window closed, quit): nothing was captured for them.
    for (auto& [at, paths] : s.captures) {
        for (const auto& path : paths)
            s.capturesMissed.push_back(path);
    }
    if (!s.capturesMissed.empty()) {
        std::fprintf(stderr, "candela: run ended after %u frames; nothing captured for %s\n",
                     std::uint32_t(stats.frameMs.size()), s.capturesMissed.front().c_str());
        s.exitCode = kExitFailure;
    }
    if (!s.audio->finish()) s.exitCode = kExitFailure;
    if (s.recorder) {
        if (std::string e = s.recorder->write(*options.recordInput); !e.empty()) {
            std::fprintf(stderr, "candela: %s\n", e.c_str());
            s.exitCode = kExitFailure;
        }
    }
    if (options.frameGraph) {
        if (std::string e = content::writeFileAtomically(*options.frameGraph, frameGraphDot);
            !e.empty()) {
            std::fprintf(stderr, "candela: %s\n", e.c_str());
            s.exitCode = kExitFailure;
        }
    }
    if (options.stats) {
        if (std::string e = writeStatsJson(*options.stats, stats); !e.empty()) {
            std::fprintf(stderr, "candela: %s\n", e.c_str());
            s.exitCode = kExitFailure;
        }
    }
    if (stats.validationMessages > 0 && options.validation == render::ValidationMode::Required) {
        std::fprintf(stderr, "candela: %u validation messages\n", stats.validationMessages);
        s.exitCode = kExitValidation;
    }
    return s.exitCode;
}

}  // namespace candela::runtime
