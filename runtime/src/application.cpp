#include "candela/runtime/application.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>

#include "candela/content/atomic_file_write.h"
#include "candela/render/frame_capture.h"
#include "candela/render/frame_submitter.h"
#include "candela/render/renderer.h"
#include "candela/render/scene_resources.h"
#include "candela/render/swapchain.h"
#include "candela/runtime/exit_code.h"
#include "candela/runtime/frame_extraction.h"
#include "candela/runtime/light_table.h"
#include "candela/runtime/sky_loader.h"
#include "candela/runtime/window.h"

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

// --brdf, else the scene file's "brdf", else the energy-conserving default.
render::BrdfModel brdfFor(const ApplicationOptions& options, const SceneWorld* world) {
    if (options.brdf) return *options.brdf;
    if (world && world->sceneBrdf()) {
        return *world->sceneBrdf() == content::SceneBrdf::Ue4 ? render::BrdfModel::Ue4
                                                              : render::BrdfModel::EnergyConserving;
    }
    return render::BrdfModel::EnergyConserving;
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

struct Application::Session {
    std::unique_ptr<render::GpuContext> context;
    std::unique_ptr<render::Renderer> renderer;
    std::unique_ptr<render::FrameSubmitter> submitter;
    std::unique_ptr<render::SceneResources> resources;
    std::unique_ptr<LightTable> lightTable;
    std::unique_ptr<render::FrameReadback> readback;
    std::unique_ptr<Window> window;
    ExtractedFrame extracted;
    // Captures wanted per frame index (kLastFrame resolved to the run's last frame).
    std::map<std::uint32_t, std::vector<std::filesystem::path>> captures;
    std::vector<std::filesystem::path> capturesMissed;
    int exitCode = kExitOk;
    SkyLoader sky;
};

// Loads the sky when the file named by the options or the world's Sky component changes
// (cached precomputation makes a reload of a known sky cheap).
void Application::updateSky(Session& s) {
    if (!s.sky.update(*world_, s.extracted, *s.context, *s.submitter, *s.resources, "candela")) {
        return;
    }
    if (s.resources->environment()) {
        stats_.environment = s.resources->environment()->stats();
    } else {
        stats_.environment.reset();
    }
}

Application::Application(ApplicationOptions options)
    : options_(std::move(options)), world_(std::make_unique<SceneWorld>()) {}

Application::~Application() = default;

void Application::setWorld(std::unique_ptr<SceneWorld> world) {
    world_ = std::move(world);
}

void Application::addSystem(std::string name, System system) {
    systems_.emplace_back(std::move(name), std::move(system));
}

void Application::addLayer(std::shared_ptr<FrameLayer> layer) {
    layers_.push_back(std::move(layer));
}

int Application::run() {
    std::vector<std::filesystem::path> outputs;
    for (const FrameCapture& c : options_.captures) {
        std::string ext = c.path.extension().string();
        if (ext != ".png" && ext != ".exr") {
            std::fprintf(stderr, "candela: %s: captures must end in .png or .exr\n",
                         c.path.c_str());
            return kExitBadArguments;
        }
        outputs.push_back(c.path);
    }
    if (options_.stats) outputs.push_back(*options_.stats);
    if (options_.frameGraph) outputs.push_back(*options_.frameGraph);
    for (const std::filesystem::path& path : outputs) {
        if (std::string e = checkWritable(path); !e.empty()) {
            std::fprintf(stderr, "candela: %s\n", e.c_str());
            return kExitBadArguments;
        }
    }
    bool headless = options_.headless || !displayAvailable();
    if (!options_.headless && headless) {
        std::fprintf(stderr, "candela: no display found, rendering headless\n");
    }
    std::uint32_t frames = options_.frames != 0 ? options_.frames : (headless ? 1 : 0);
    return runSession(headless, frames);
}

int Application::runSession(bool headless, std::uint32_t frames) {
    stats_ = FrameStats{};
    stats_.width = options_.width;
    stats_.height = options_.height;
    input_ = InputState{};
    quitRequested_ = false;
    Session s;
    s.sky = SkyLoader(options_.environment);
    std::string frameGraphDot;
    for (const FrameCapture& c : options_.captures) {
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
    // A script (or a headless run) uses the fixed step, so its frames repeat exactly.
    const bool fixedStep = headless || options_.inputScript.has_value();
    try {
        render::GpuContextOptions gpuOptions;
        gpuOptions.validation = options_.validation;
        if (const char* preferred = std::getenv("CANDELA_DEVICE")) {
            gpuOptions.preferredDevice = preferred;
        }
        if (!headless) {
            gpuOptions.instanceExtensions = Window::requiredInstanceExtensions();
            gpuOptions.swapchain = true;
            s.window = std::make_unique<Window>(options_.width, options_.height, options_.title);
            if (!options_.inputScript) s.window->setInputTarget(&input_);
            if (options_.captureCursor) s.window->setCursorCaptured(true);
        }
        s.context = std::make_unique<render::GpuContext>(gpuOptions);
        render::RendererOptions rendererOptions;
        rendererOptions.lightCulling = options_.lightCulling;
        rendererOptions.lightAssignment = options_.lightAssignment;
        rendererOptions.countLightPairs = options_.countLightPairs;
        rendererOptions.ibl = options_.ibl;
        rendererOptions.brdf = brdfFor(options_, world_.get());
        s.renderer = std::make_unique<render::Renderer>(*s.context, options_.width, options_.height,
                                                        rendererOptions);
        s.submitter = std::make_unique<render::FrameSubmitter>(*s.context);
        s.resources = std::make_unique<render::SceneResources>(*s.context);
        stats_.device = s.context->deviceName();
        if (!s.captures.empty()) {
            s.readback = std::make_unique<render::FrameReadback>(*s.context, options_.width,
                                                                 options_.height);
        }
        for (auto& layer : layers_)
            layer->start(*s.context, s.window.get());

        VkSurfaceKHR surface = VK_NULL_HANDLE;
        std::unique_ptr<render::Swapchain> swapchain;
        if (s.window) {
            surface = s.window->createSurface(s.context->instance());
            swapchain = std::make_unique<render::Swapchain>(*s.context, surface, options_.width,
                                                            options_.height);
        }
        const Clock::time_point runStart = Clock::now();
        double previousSeconds = 0.0;
        for (std::uint32_t i = 0; frames == 0 || i < frames; ++i) {
            Clock::time_point start = Clock::now();
            input_.beginFrame();
            if (s.window) s.window->pollEvents();
            if (options_.inputScript) options_.inputScript->apply(i, input_);
            if (input_.closeRequested || quitRequested_) break;
            if (s.window && s.window->shouldClose()) break;
            if (s.window && !windowTitle_.empty()) {
                s.window->setTitle(windowTitle_);
                windowTitle_.clear();
            }

            uint32_t imageIndex = 0;
            if (s.window) {
                if (s.window->consumeResized()) {
                    uint32_t w, h;
                    s.window->framebufferSize(w, h);
                    s.submitter->waitIdle();
                    swapchain->recreate(w, h);
                    // Without captures the render follows the window.
                    if (s.captures.empty()) s.renderer->resize(w, h);
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

            FrameContext frame;
            frame.frame = i;
            frame.seconds = fixedStep
                                ? double(i) * options_.fixedStepSeconds
                                : std::chrono::duration<double>(Clock::now() - runStart).count();
            frame.deltaSeconds = fixedStep ? (i == 0 ? 0.0 : options_.fixedStepSeconds)
                                           : frame.seconds - previousSeconds;
            previousSeconds = frame.seconds;
            frame.input = &input_;
            frame.headless = headless;
            frame.width = s.renderer->width();
            frame.height = s.renderer->height();

            render::SceneResources* resources = nullptr;
            if (world_) {
                for (auto& [name, system] : systems_)
                    system(*world_, frame);
                world_->updateTransforms();
                float aspect = float(s.renderer->width()) / float(s.renderer->height());
                if (!s.lightTable) s.lightTable = std::make_unique<LightTable>(world_->registry);
                extractFrame(world_->registry, *s.lightTable, *s.resources, aspect, s.extracted);
                frame_.scene.camera = s.extracted.camera;
                frame_.scene.draws = s.extracted.draws;
                frame_.scene.lights = s.extracted.lights;
                frame_.scene.changedLights = s.extracted.changedLights;
                frame_.scene.lightsRestructured = s.extracted.lightsRestructured;
                frame_.scene.skyIntensity = s.extracted.skyIntensity;
                frame_.text = std::move(s.extracted.text);
                updateSky(s);
                resources = s.resources.get();
            }
            VkCommandBuffer cmd = s.renderer->recordFrame(*s.submitter, frame_, resources);
            for (auto& layer : layers_)
                layer->record(cmd, *s.renderer, frame, stats_);
            auto wanted = s.captures.find(i);
            if (wanted != s.captures.end()) s.readback->recordCopy(cmd, *s.renderer);
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
            stats_.frameMs.push_back(millisecondsSince(start));
            stats_.addRendererStats(s.renderer->collectStats());
            if (wanted != s.captures.end()) {
                render::CapturedFrame captured = s.readback->read();
                if (size_t bad = captured.nonFiniteHdrValues()) {
                    std::fprintf(stderr, "candela: warning: capture holds %zu NaN/Inf values\n",
                                 bad);
                }
                for (const std::filesystem::path& path : wanted->second) {
                    if (std::string e = render::writeCapture(path, captured); !e.empty()) {
                        std::fprintf(stderr, "candela: %s\n", e.c_str());
                        s.exitCode = kExitFailure;
                    } else {
                        std::printf("captured %s\n", path.c_str());
                    }
                }
                s.captures.erase(wanted);
            }
        }
        s.submitter->waitIdle();
        for (auto& layer : layers_)
            layer->stop();
        swapchain.reset();
        if (surface != VK_NULL_HANDLE) vkDestroySurfaceKHR(s.context->instance(), surface, nullptr);
        if (s.window) s.window->setInputTarget(nullptr);
        stats_.features = s.renderer->features();
        if (options_.frameGraph) frameGraphDot = s.renderer->frameGraphDot();
        stats_.validationMessages = s.context->validationMessages();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "candela: %s\n", e.what());
        // Layers hold device objects: they go before the device does.
        if (s.submitter) {
            for (auto& layer : layers_) {
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
                     framesRendered(), s.capturesMissed.front().c_str());
        s.exitCode = kExitFailure;
    }
    if (options_.frameGraph) {
        if (std::string e = content::writeFileAtomically(*options_.frameGraph, frameGraphDot);
            !e.empty()) {
            std::fprintf(stderr, "candela: %s\n", e.c_str());
            s.exitCode = kExitFailure;
        }
    }
    if (options_.stats) {
        if (std::string e = writeStatsJson(*options_.stats, stats_); !e.empty()) {
            std::fprintf(stderr, "candela: %s\n", e.c_str());
            s.exitCode = kExitFailure;
        }
    }
    if (stats_.validationMessages > 0 && options_.validation == render::ValidationMode::Required) {
        std::fprintf(stderr, "candela: %u validation messages\n", stats_.validationMessages);
        s.exitCode = kExitValidation;
    }
    return s.exitCode;
}

}  // namespace candela::runtime
