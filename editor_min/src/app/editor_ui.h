#pragma once
// The editor's ImGui frame: menu bar (File, Edit, Create), keyboard shortcuts, the hierarchy
// and inspector panels docked left and right, and the light gizmos over the viewport between.
#include <string>

#include "app/inspector_panel.h"
#include "candela/render/frame_scene.h"

namespace candela::editor {

class EditorScene;

struct EditorUiState {
    InspectorState inspector;
    std::string status;          // last save result, shown in the menu bar
    bool saveRequested = false;  // File > Save or Ctrl+S; the app saves and clears it
    bool quitRequested = false;  // File > Quit
};

// Builds the UI for one frame (between ImGuiLayer::beginFrame and endFrame). `camera` is the
// frame's scene camera (null: none, no gizmos).
void drawEditorUi(EditorScene& scene, EditorUiState& state, const render::CameraView* camera,
                  float width, float height);

}  // namespace candela::editor
