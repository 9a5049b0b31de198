#include "app/editor_app.h"

#include <chrono>
#include <cstdio>
#include <exception>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <optional>
#include <string_view>

#include "app/editor_script.h"
#include "app/editor_ui.h"
#include "app/editor_window.h"
#include "app/scene_opening.h"
#include "candela/content/components/camera.h"
#include "candela/render/exposure.h"
#include "candela/render/frame_capture.h"
#include "candela/render/frame_submitter.h"
#include "candela/render/gpu_context.h"
#include "candela/render/renderer.h"
#include "candela/render/scene_resources.h"
#include "candela/render/swapchain.h"
#include "candela/runtime/frame_extraction.h"
#include "candela/runtime/light_table.h"
#include "candela/runtime/sky_loader.h"
#include "candela/ui/imgui_layer.h"
#include "candela/ui/imgui_renderer.h"

namespace candela::editor {

namespace {

using Clock = std::chrono::steady_clock;

// The open scene with what the renderer keeps about it; replaced as a whole by `open`.
struct Session {
    OpenedScene opened;
    std::unique_ptr<render::SceneResources> resources;
    std::unique_ptr<runtime::LightTable> lights;
    runtime::ExtractedFrame extracted;
    runtime::SkyLoader sky;  // the scene's Sky component, loaded as `candela run` does

    void reset(render::GpuContext& context, OpenedScene scene) {
        lights.reset();  // unhooks from the old registry before it goes
        extracted = {};
        sky = runtime::SkyLoader();
        opened = std::move(scene);
        resources = std::make_unique<render::SceneResources>(context);
        lights = std::make_unique<runtime::LightTable>(opened.world->registry);
    }
};

struct FrameRequests {
    std::optional<std::filesystem::path> screenshot;
    bool quit = false;
};

// `text` from `offset` on, without the blanks in front.
std::string trimmedAfter(const std::string& text, size_t offset) {
    const size_t begin = text.find_first_not_of(" \t", offset);
    return begin == std::string::npos ? std::string() : text.substr(begin);
}

// Runs this frame's script step; false with `error` when it failed.
bool runScriptStep(EditorScript& script, Session& session, render::GpuContext& context,
                   render::FrameSubmitter& submitter, FrameRequests& requests, std::string& error) {
    const ScriptStep* step = script.nextStep();
    if (!step) return true;
    EditorScene& scene = *session.opened.scene;
    bool handled = false;
    if (!runModelStep(scene, *step, handled, error)) return false;
    if (handled) return true;
    if (step->verb == "open") {
        std::string why;
        std::optional<OpenedScene> opened = openScene(step->text, why);
        if (!opened) {
            error = step->where + ": open: " + why;
            return false;
        }
        submitter.waitIdle();  // the old scene's GPU resources may still be in use
        session.reset(context, std::move(*opened));
    } else if (step->verb == "save") {
        // `save --replace-read-only [<path>]`: the user's explicit yes for a read-only file.
        constexpr std::string_view kReplaceReadOnly = "--replace-read-only";
        std::string text = step->text;
        const bool replaceReadOnly = text.starts_with(kReplaceReadOnly);
        if (replaceReadOnly) text = trimmedAfter(text, kReplaceReadOnly.size());
        const std::filesystem::path path =
            text.empty() ? session.opened.savePath : std::filesystem::path(text);
        if (std::string why = scene.save(path, replaceReadOnly); !why.empty()) {
            error = step->where + ": save: " + why;
            return false;
        }
        std::printf("saved %s\n", path.c_str());
    } else if (step->verb == "screenshot") {
        requests.screenshot = std::filesystem::path(step->text);
    } else if (step->verb == "quit") {
        requests.quit = true;
    }
    return true;
}

// What the viewport shows when the scene has no camera: 50 degrees, sunny-16 exposure, from
// 5 m in front of the origin.
render::CameraView defaultCamera(float aspect) {
    const content::Camera camera;
    render::CameraView view;
    view.position = glm::vec3(0.0f, 1.0f, 5.0f);
    view.view = glm::lookAt(view.position, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    view.projection = render::reverseZPerspective(camera.verticalFov, aspect, camera.nearPlane);
    view.ev100 = render::ev100FromCamera(camera);
    view.nearPlane = camera.nearPlane;
    view.farPlane = camera.farPlane;
    return view;
}

render::GpuContextOptions gpuOptions(const EditorOptions& options) {
    render::GpuContextOptions gpu;
    gpu.validation = options.validation;
    gpu.instanceExtensions = EditorWindow::requiredInstanceExtensions();
    gpu.swapchain = true;
    if (const char* preferred = std::getenv("CANDELA_DEVICE")) gpu.preferredDevice = preferred;
    return gpu;
}

}  // namespace

int runEditor(const EditorOptions& options) {
    std::string error;
    std::optional<EditorScript> script;
    if (options.script) {
        script = EditorScript::load(*options.script, error);
        if (!script) {
            std::fprintf(stderr, "candela-editor: %s\n", error.c_str());
            return kEditorBadArguments;
        }
    }
    std::optional<OpenedScene> initial =
        options.scene ? openScene(*options.scene, error) : std::optional(emptyScene());
    if (!initial) {
        std::fprintf(stderr, "candela-editor: %s\n", error.c_str());
        return kEditorBadArguments;
    }

    int exitCode = kEditorOk;
    uint32_t validationMessages = 0;
    try {
        // Declaration order is destruction order in reverse: the window outlives the device
        // objects, the ImGui layer outlives its renderer.
        EditorWindow window(options.width, options.height, "Candela Editor");
        render::GpuContext context(gpuOptions(options));
        uint32_t width = 0, height = 0;
        window.framebufferSize(width, height);
        VkSurfaceKHR surface = window.createSurface(context.instance());
        {
            render::Swapchain swapchain(context, surface, width, height);
            render::Renderer renderer(context, width, height);
            render::FrameSubmitter submitter(context);
            ui::ImGuiLayer layer(window.handle());
            ui::ImGuiRenderer imgui(context);
            Session session;
            session.reset(context, std::move(*initial));
            EditorUiState ui;
            render::FrameInputs inputs;
            Clock::time_point last = Clock::now();

            for (uint32_t frame = 0; options.frames == 0 || frame < options.frames; ++frame) {
                window.pollEvents();
                if (window.shouldClose() || ui.quitRequested) break;
                uint32_t w = 0, h = 0;
                window.framebufferSize(w, h);
                if (w != renderer.width() || h != renderer.height()) {
                    submitter.waitIdle();
                    swapchain.recreate(w, h);
                    renderer.resize(w, h);
                }

                FrameRequests requests;
                if (script &&
                    !runScriptStep(*script, session, context, submitter, requests, error)) {
                    std::fprintf(stderr, "candela-editor: %s\n", error.c_str());
                    exitCode = kEditorFailure;
                    break;
                }
                EditorScene& scene = *session.opened.scene;

                // The frame shows the scene as edited so far; UI edits below show next frame.
                session.opened.world->updateTransforms();
                runtime::extractFrame(session.opened.world->registry, *session.lights,
                                      *session.resources, float(w) / float(h), session.extracted);
                const runtime::ExtractedFrame& x = session.extracted;
                inputs.clearRadiance = session.opened.background;
                inputs.scene.skyIntensity = x.skyIntensity;
                session.sky.update(*session.opened.world, x, context, submitter, *session.resources,
                                   "candela-editor");
                inputs.scene.draws = x.draws;
                inputs.scene.lights = x.lights;
                inputs.scene.changedLights = x.changedLights;
                inputs.scene.lightsRestructured = x.lightsRestructured;

                const Clock::time_point now = Clock::now();
                layer.beginFrame(float(w), float(h),
                                 std::chrono::duration<float>(now - last).count());
                last = now;
                inputs.scene.camera = drawEditorUi(
                    scene, ui, x.hasCamera ? x.camera : defaultCamera(float(w) / float(h)),
                    x.hasCamera, float(w), float(h));
                if (ui.saveRequested || ui.saveOverReadOnlyRequested) {
                    const std::string why =
                        scene.save(session.opened.savePath, ui.saveOverReadOnlyRequested);
                    ui.saveRequested = ui.saveOverReadOnlyRequested = false;
                    ui.status = why.empty() ? "saved " + session.opened.savePath.string() : why;
                }
                const ImDrawData* draw = layer.endFrame();

                submitter.waitIdle();
                uint32_t imageIndex = 0;
                if (!swapchain.acquire(submitter.imageAvailable(), imageIndex)) {
                    swapchain.recreate(w, h);
                    continue;
                }
                VkCommandBuffer cmd =
                    renderer.recordFrame(submitter, inputs, session.resources.get());
                imgui.record(cmd, *draw, renderer.ldrTarget(),
                             VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
                std::unique_ptr<render::FrameReadback> readback;
                if (requests.screenshot) {
                    readback = std::make_unique<render::FrameReadback>(context, w, h);
                    readback->recordCopy(cmd, renderer);
                }
                swapchain.recordBlit(cmd, renderer.ldrTarget(), imageIndex);
                submitter.submit(submitter.imageAvailable(), swapchain.renderFinished(imageIndex));
                if (!swapchain.present(imageIndex)) {
                    submitter.waitIdle();
                    swapchain.recreate(w, h);
                }
                submitter.waitIdle();
                if (readback) {
                    if (std::string why =
                            render::writeCapture(*requests.screenshot, readback->read());
                        !why.empty()) {
                        std::fprintf(stderr, "candela-editor: %s\n", why.c_str());
                        exitCode = kEditorFailure;
                        break;
                    }
                    std::printf("captured %s\n", requests.screenshot->c_str());
                }
                if (requests.quit) break;
            }
            submitter.waitIdle();
        }
        vkDestroySurfaceKHR(context.instance(), surface, nullptr);
        validationMessages = context.validationMessages();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "candela-editor: %s\n", e.what());
        return kEditorFailure;
    }
    if (validationMessages > 0 && options.validation == render::ValidationMode::Required) {
        std::fprintf(stderr, "candela-editor: %u validation messages\n", validationMessages);
        return kEditorValidation;
    }
    return exitCode;
}

}  // namespace candela::editor
