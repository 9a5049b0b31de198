#pragma once
// The editor's ImGui frame: menu bar (File, Edit, Create), keyboard shortcuts, the hierarchy
// and inspector panels docked left and right, and the light gizmos over the viewport between.
#include <string>

#include "app/editor_camera.h"
#include "app/inspector_panel.h"
#include "candela/render/frame_scene.h"

namespace candela::editor {

class EditorScene;

struct EditorUiState {
    InspectorState inspector;
    EditorCamera camera;
    std::string status;          // last save result, shown in the menu bar
    bool saveRequested = false;  // File > Save or Ctrl+S; the app saves and clears it
    // File > Save over read-only file: the user's explicit yes to replacing a 0444 scene.
    bool saveOverReadOnlyRequested = false;
    bool quitRequested = false;  // File > Quit
};

// Builds the UI for one frame (between ImGuiLayer::beginFrame and endFrame) and moves the
// viewport camera; returns the camera the frame renders through. `sceneCamera` is the scene's
// (a default one when the scene has none).
render::CameraView drawEditorUi(EditorScene& scene, EditorUiState& state,
                                const render::CameraView& sceneCamera, bool sceneHasCamera,
                                float width, float height);

}  // namespace candela::editor
