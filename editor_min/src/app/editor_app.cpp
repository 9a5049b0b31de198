#include "app/editor_app.h"

#include <cstdio>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <optional>
#include <string_view>

#include "app/editor_layer.h"
#include "app/editor_script.h"
#include "app/editor_ui.h"
#include "app/scene_opening.h"
#include "candela/content/components/camera.h"
#include "candela/render/exposure.h"
#include "candela/render/frame_inputs.h"
#include "candela/runtime/application.h"
#include "candela/runtime/exit_code.h"
#include "candela/runtime/frame_extraction.h"

namespace candela::editor {

namespace {

// `text` from `offset` on, without the blanks in front.
std::string trimmedAfter(const std::string& text, size_t offset) {
    const size_t begin = text.find_first_not_of(" \t", offset);
    return begin == std::string::npos ? std::string() : text.substr(begin);
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

bool displayAvailable() {
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (display && *display) || (wayland && *wayland);
}

// The editor on the runtime's application: the open scene is the application's world, the
// script runs at each frame's start, the UI is built once the frame's scene is extracted and
// drawn by the EditorLayer's pass.
class Editor {
public:
    Editor(runtime::Application& app, OpenedScene opened, std::optional<EditorScript> script)
        : app_(app), script_(std::move(script)), layer_(std::make_shared<EditorLayer>()) {
        show(std::move(opened));
        app_.addLayer(layer_);
        app_.onFrameStart([this](const runtime::FrameContext&) { runScriptStep(); });
        app_.onBeforeRender([this](render::FrameInputs& inputs, const runtime::ExtractedFrame& x,
                                   const runtime::FrameContext& frame) {
            drawUi(inputs, x, frame);
            // An edit (or undo) shows at once, with nothing of the old state blended in
            // by TAA's history.
            if (scene_->revision() != shownRevision_) {
                shownRevision_ = scene_->revision();
                app_.restartTemporalHistory();
            }
        });
    }

    int exitCode() const { return exitCode_; }

private:
    // The scene becomes the application's world (from the next systems run on); the model that
    // edits it is replaced here, before the old world goes.
    void show(OpenedScene opened) {
        app_.setClearRadiance(opened.background);
        opened.world->simulatePhysics = false;  // edited, not played: bodies stay put
        app_.setWorld(std::move(opened.world));
        scene_ = std::move(opened.scene);
        savePath_ = std::move(opened.savePath);
    }

    void fail(const std::string& error) {
        std::fprintf(stderr, "candela-editor: %s\n", error.c_str());
        exitCode_ = kEditorFailure;
        app_.requestQuit();
    }

    // This frame's script step (one per frame); a failed step ends the run.
    void runScriptStep() {
        if (!script_ || exitCode_ != kEditorOk) return;
        const ScriptStep* step = script_->nextStep();
        if (!step) return;
        std::string error;
        bool handled = false;
        if (!runModelStep(*scene_, *step, handled, error)) return fail(error);
        if (handled) return;
        if (step->verb == "open") {
            std::string why;
            std::optional<OpenedScene> opened = openScene(step->text, why);
            if (!opened) return fail(step->where + ": open: " + why);
            show(std::move(*opened));
        } else if (step->verb == "save") {
            // `save --replace-read-only [<path>]`: the user's explicit yes for a read-only file.
            constexpr std::string_view kReplaceReadOnly = "--replace-read-only";
            std::string text = step->text;
            const bool replaceReadOnly = text.starts_with(kReplaceReadOnly);
            if (replaceReadOnly) text = trimmedAfter(text, kReplaceReadOnly.size());
            const std::filesystem::path path =
                text.empty() ? savePath_ : std::filesystem::path(text);
            if (std::string why = scene_->save(path, replaceReadOnly); !why.empty()) {
                return fail(step->where + ": save: " + why);
            }
            std::printf("saved %s\n", path.c_str());
        } else if (step->verb == "screenshot") {
            app_.captureFrame(step->text);
        } else if (step->verb == "quit") {
            app_.requestQuit();  // after this frame
        }
    }

    // The UI for this frame; it moves the viewport camera, which the frame then renders
    // through (the scene camera unless detached).
    void drawUi(render::FrameInputs& inputs, const runtime::ExtractedFrame& x,
                const runtime::FrameContext& frame) {
        if (!layer_->started()) return;
        const float w = float(frame.width), h = float(frame.height);
        layer_->beginFrame(w, h, float(frame.deltaSeconds));
        inputs.scene.camera = drawEditorUi(
            *scene_, ui_, x.hasCamera ? x.camera : defaultCamera(w / h), x.hasCamera, w, h);
        // The inspector's ambient occlusion edits show in this very frame.
        if (const auto& ao = scene_->sceneAmbientOcclusion()) {
            inputs.scene.aoRadius = ao->radius;
            inputs.scene.aoIntensity = ao->intensity;
        }
        if (ui_.saveRequested || ui_.saveOverReadOnlyRequested) {
            const std::string why = scene_->save(savePath_, ui_.saveOverReadOnlyRequested);
            ui_.saveRequested = ui_.saveOverReadOnlyRequested = false;
            ui_.status = why.empty() ? "saved " + savePath_.string() : why;
        }
        layer_->endFrame();
        if (ui_.quitRequested) app_.requestQuit();
    }

    runtime::Application& app_;
    std::optional<EditorScript> script_;
    std::shared_ptr<EditorLayer> layer_;
    std::unique_ptr<EditorScene> scene_;
    std::filesystem::path savePath_;
    EditorUiState ui_;
    uint64_t shownRevision_ = 0;
    int exitCode_ = kEditorOk;
};

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
    if (!displayAvailable()) {
        std::fprintf(stderr,
                     "candela-editor: cannot open a window (no display; run under "
                     "xvfb-run -a)\n");
        return kEditorFailure;
    }
    std::optional<OpenedScene> initial =
        options.scene ? openScene(*options.scene, error) : std::optional(emptyScene());
    if (!initial) {
        std::fprintf(stderr, "candela-editor: %s\n", error.c_str());
        return kEditorBadArguments;
    }

    runtime::ApplicationOptions appOptions;
    appOptions.title = "Candela Editor";
    appOptions.width = options.width;
    appOptions.height = options.height;
    appOptions.frames = options.frames;
    appOptions.validation = options.validation;
    appOptions.physicsDebug = options.physicsDebug;
    // Declared first: the application (and the world it owns) outlives the editor's model.
    runtime::Application app(std::move(appOptions));
    Editor editor(app, std::move(*initial), std::move(script));
    const int appExit = app.run();
    // The run's own failures (device, validation) first, then the editor's (a script step).
    return appExit != runtime::kExitOk ? appExit : editor.exitCode();
}

}  // namespace candela::editor
