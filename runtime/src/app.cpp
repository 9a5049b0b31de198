#include "app.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>

#include "candela/render/frame_capture.h"
#include "candela/render/frame_submitter.h"
#include "candela/render/gpu_context.h"
#include "candela/render/renderer.h"
#include "candela/render/scene_resources.h"
#include "candela/render/swapchain.h"
#include "frame_extraction.h"
#include "frame_stats.h"
#include "scene_source.h"
#include "window.h"

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

// Headless runs advance scene time by a fixed step so captures are the same run after run.
constexpr double kHeadlessSecondsPerFrame = 1.0 / 30.0;

struct Session {
    std::unique_ptr<render::GpuContext> context;
    std::unique_ptr<render::Renderer> renderer;
    std::unique_ptr<render::FrameSubmitter> submitter;
    std::unique_ptr<render::SceneResources> resources;
    std::unique_ptr<LightTable> lightTable;
    ExtractedFrame extracted;
};

// Animates and reads the scene into the frame's inputs; returns the resources to draw with.
render::SceneResources* prepareFrame(Session& s, LoadedScene& scene, double seconds) {
    if (!scene.world) return nullptr;
    if (scene.animate) scene.animate(*scene.world, seconds);
    scene.world->updateTransforms();
    float aspect = float(s.renderer->width()) / float(s.renderer->height());
    if (!s.lightTable) s.lightTable = std::make_unique<LightTable>(scene.world->registry);
    extractFrame(scene.world->registry, *s.lightTable, *s.resources, aspect, s.extracted);
    scene.frame.scene.camera = s.extracted.camera;
    scene.frame.scene.draws = s.extracted.draws;
    scene.frame.scene.lights = s.extracted.lights;
    scene.frame.scene.changedLights = s.extracted.changedLights;
    scene.frame.scene.lightsRestructured = s.extracted.lightsRestructured;
    return s.resources.get();
}

void renderHeadless(Session& s, LoadedScene& scene, uint32_t frames,
                    render::FrameReadback* readback, FrameStats& stats) {
    for (uint32_t i = 0; i < frames; ++i) {
        Clock::time_point start = Clock::now();
        render::SceneResources* resources = prepareFrame(s, scene, i * kHeadlessSecondsPerFrame);
        VkCommandBuffer cmd = s.renderer->recordFrame(*s.submitter, scene.frame, resources);
        bool last = i + 1 == frames;
        if (last && readback) readback->recordCopy(cmd, *s.renderer);
        s.submitter->submit();
        s.submitter->waitIdle();
        stats.frameMs.push_back(millisecondsSince(start));
        stats.addRendererStats(s.renderer->collectStats());
    }
}

void renderWindowed(Session& s, Window& window, render::Swapchain& swapchain, LoadedScene& scene,
                    uint32_t frames, render::FrameReadback*& readback, const RunOptions& options,
                    FrameStats& stats) {
    const Clock::time_point runStart = Clock::now();
    for (uint32_t i = 0; (frames == 0 || i < frames) && !window.shouldClose(); ++i) {
        Clock::time_point start = Clock::now();
        window.pollEvents();
        if (window.consumeResized()) {
            uint32_t w, h;
            window.framebufferSize(w, h);
            s.submitter->waitIdle();
            swapchain.recreate(w, h);
            // Without a fixed --size the render follows the window.
            if (options.captures.empty()) s.renderer->resize(w, h);
        }
        uint32_t imageIndex = 0;
        s.submitter->waitIdle();
        if (!swapchain.acquire(s.submitter->imageAvailable(), imageIndex)) {
            uint32_t w, h;
            window.framebufferSize(w, h);
            swapchain.recreate(w, h);
            continue;
        }
        render::SceneResources* resources =
            prepareFrame(s, scene, std::chrono::duration<double>(Clock::now() - runStart).count());
        VkCommandBuffer cmd = s.renderer->recordFrame(*s.submitter, scene.frame, resources);
        bool last = frames != 0 && i + 1 == frames;
        if (last && readback) readback->recordCopy(cmd, *s.renderer);
        swapchain.recordBlit(cmd, s.renderer->ldrTarget(), imageIndex);
        s.submitter->submit(s.submitter->imageAvailable(), swapchain.renderFinished(imageIndex));
        if (!swapchain.present(imageIndex)) {
            uint32_t w, h;
            window.framebufferSize(w, h);
            s.submitter->waitIdle();
            swapchain.recreate(w, h);
        }
        s.submitter->waitIdle();
        stats.frameMs.push_back(millisecondsSince(start));
        stats.addRendererStats(s.renderer->collectStats());
    }
    // Closed before the last frame: nothing complete to capture from the readback.
    if (frames == 0 || stats.frameMs.size() < frames) readback = nullptr;
}

}  // namespace

int runScene(const RunOptions& options) {
    std::string error;
    std::optional<LoadedScene> scene = loadScene(options.scene, error);
    if (!scene) {
        std::fprintf(stderr, "candela: %s\n", error.c_str());
        return kExitBadArguments;
    }
    std::vector<std::filesystem::path> outputs = options.captures;
    if (options.stats) outputs.push_back(*options.stats);
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
    uint32_t frames = options.frames != 0 ? options.frames : (headless ? 1 : 0);

    FrameStats stats;
    stats.width = options.width;
    stats.height = options.height;
    std::optional<render::CapturedFrame> captured;
    Session s;
    try {
        render::GpuContextOptions gpuOptions;
        gpuOptions.validation = options.validation;
        if (const char* preferred = std::getenv("CANDELA_DEVICE")) {
            gpuOptions.preferredDevice = preferred;
        }
        std::unique_ptr<Window> window;
        if (!headless) {
            gpuOptions.instanceExtensions = Window::requiredInstanceExtensions();
            gpuOptions.swapchain = true;
            window = std::make_unique<Window>(options.width, options.height, "Candela");
        }
        s.context = std::make_unique<render::GpuContext>(gpuOptions);
        render::RendererOptions rendererOptions;
        rendererOptions.lightCulling = options.lightCulling;
        rendererOptions.countLightPairs = options.stats.has_value();
        s.renderer = std::make_unique<render::Renderer>(*s.context, options.width, options.height,
                                                        rendererOptions);
        s.submitter = std::make_unique<render::FrameSubmitter>(*s.context);
        s.resources = std::make_unique<render::SceneResources>(*s.context);
        stats.device = s.context->deviceName();
        std::unique_ptr<render::FrameReadback> readbackStorage;
        if (!options.captures.empty()) {
            readbackStorage =
                std::make_unique<render::FrameReadback>(*s.context, options.width, options.height);
        }
        render::FrameReadback* readback = readbackStorage.get();
        if (headless) {
            renderHeadless(s, *scene, frames, readback, stats);
        } else {
            VkSurfaceKHR surface = window->createSurface(s.context->instance());
            {
                render::Swapchain swapchain(*s.context, surface, options.width, options.height);
                renderWindowed(s, *window, swapchain, *scene, frames, readback, options, stats);
                s.submitter->waitIdle();
            }
            vkDestroySurfaceKHR(s.context->instance(), surface, nullptr);
        }
        if (readback) captured = readback->read();
        stats.features = s.renderer->features();
        stats.validationMessages = s.context->validationMessages();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "candela: %s\n", e.what());
        return kExitFailure;
    }

    int exitCode = kExitOk;
    if (!options.captures.empty() && !captured) {
        std::fprintf(stderr, "candela: window closed before frame %u; nothing captured\n", frames);
        exitCode = kExitFailure;
    }
    for (const std::filesystem::path& capture : options.captures) {
        if (!captured) break;
        if (std::string e = render::writeCapture(capture, *captured); !e.empty()) {
            std::fprintf(stderr, "candela: %s\n", e.c_str());
            exitCode = kExitFailure;
        } else {
            std::printf("captured %s\n", capture.c_str());
        }
    }
    if (captured) {
        if (size_t bad = captured->nonFiniteHdrValues()) {
            std::fprintf(stderr, "candela: warning: capture holds %zu NaN/Inf values\n", bad);
        }
    }
    if (options.stats) {
        if (std::string e = writeStatsJson(*options.stats, stats); !e.empty()) {
            std::fprintf(stderr, "candela: %s\n", e.c_str());
            exitCode = kExitFailure;
        }
    }
    if (stats.validationMessages > 0 && options.validation == render::ValidationMode::Required) {
        std::fprintf(stderr, "candela: %u validation messages\n", stats.validationMessages);
        exitCode = kExitValidation;
    }
    return exitCode;
}

}  // namespace candela::runtime
