#include "app/editor_ui.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <string>

#include "app/hierarchy_panel.h"
#include "app/light_gizmo.h"
#include "model/editor_scene.h"
#include "model/structure_commands.h"

namespace candela::editor {

namespace {

void duplicateSelection(EditorScene& scene) {
    uint64_t copy = 0;
    if (scene.execute(duplicateEntity(scene, scene.selected(), &copy))) scene.selectId(copy);
}

void shortcuts(EditorScene& scene, EditorUiState& state) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput) return;  // Ctrl+Z in a text field edits the text
    // ImGui 1.86 with the GLFW backend indexes keys by GLFW key code.
    if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_Z, false)) {
        if (io.KeyShift) {
            scene.redo();
        } else {
            scene.undo();
        }
    }
    if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_Y, false)) scene.redo();
    if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_S, false)) state.saveRequested = true;
    if (io.KeyCtrl && ImGui::IsKeyPressed(GLFW_KEY_D, false)) duplicateSelection(scene);
    if (ImGui::IsKeyPressed(GLFW_KEY_DELETE, false)) {
        scene.execute(deleteEntity(scene, scene.selected()));
    }
}

float menuBar(EditorScene& scene, EditorUiState& state) {
    float height = 0.0f;
    if (!ImGui::BeginMainMenuBar()) return height;
    if (ImGui::BeginMenu("File")) {
        if (ImGui::MenuItem("Save", "Ctrl+S")) state.saveRequested = true;
        if (ImGui::MenuItem("Save over read-only file")) state.saveOverReadOnlyRequested = true;
        ImGui::Separator();
        if (ImGui::MenuItem("Quit")) state.quitRequested = true;
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
        const std::string undo = "Undo " + scene.commands().undoLabel();
        const std::string redo = "Redo " + scene.commands().redoLabel();
        if (ImGui::MenuItem(undo.c_str(), "Ctrl+Z", false, scene.commands().canUndo())) {
            scene.undo();
        }
        if (ImGui::MenuItem(redo.c_str(), "Ctrl+Y", false, scene.commands().canRedo())) {
            scene.redo();
        }
        ImGui::Separator();
        const bool selected = scene.selected() != ecs::kNullEntity;
        if (ImGui::MenuItem("Duplicate", "Ctrl+D", false, selected)) duplicateSelection(scene);
        if (ImGui::MenuItem("Delete", "Del", false, selected)) {
            scene.execute(deleteEntity(scene, scene.selected()));
        }
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
        if (ImGui::MenuItem("Scene camera", nullptr, !state.camera.detached())) {
            state.camera.attachToScene();
        }
        ImGui::TextDisabled("Hold the right mouse button in the viewport to fly (WASD, Q/E)");
        ImGui::EndMenu();
    }
    const std::string title =
        scene.sourcePath().filename().string() + (scene.modified() ? " *" : "");
    ImGui::TextDisabled("%s", title.c_str());
    if (!state.status.empty()) ImGui::TextDisabled("  %s", state.status.c_str());
    height = ImGui::GetWindowSize().y;
    ImGui::EndMainMenuBar();
    return height;
}

}  // namespace

render::CameraView drawEditorUi(EditorScene& scene, EditorUiState& state,
                                const render::CameraView& sceneCamera, bool sceneHasCamera,
                                float width, float height) {
    // Before the panels: whether the mouse is over one is known from the previous frame.
    state.camera.update(sceneCamera, sceneHasCamera);
    const render::CameraView camera = state.camera.view(sceneCamera);
    shortcuts(scene, state);
    const float top = menuBar(scene, state);
    const float hierarchyWidth = std::clamp(width * 0.25f, 160.0f, 320.0f);
    const float inspectorWidth = std::clamp(width * 0.34f, 220.0f, 400.0f);
    const ImGuiWindowFlags flags =
        ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse;

    ImGui::SetNextWindowPos(ImVec2(0.0f, top));
    ImGui::SetNextWindowSize(ImVec2(hierarchyWidth, height - top));
    if (ImGui::Begin("Hierarchy", nullptr, flags)) drawHierarchyPanel(scene);
    ImGui::End();

    ImGui::SetNextWindowPos(ImVec2(width - inspectorWidth, top));
    ImGui::SetNextWindowSize(ImVec2(inspectorWidth, height - top));
    if (ImGui::Begin("Inspector", nullptr, flags)) drawInspectorPanel(scene, state.inspector);
    ImGui::End();

    drawLightGizmos(scene, camera, ImVec2(width, height), ImGui::GetBackgroundDrawList());
    return camera;
}

}  // namespace candela::editor
