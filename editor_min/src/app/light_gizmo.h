#pragma once
// Wireframe of the selected light, projected through the scene camera onto ImGui's background
// draw list (under the panels): its attenuation radius (three great circles for a point light,
// the outer and inner cones out to the radius for a spot, a direction arrow for a directional
// light) and its source shape (sphere circles, or the tube's capsule outline along local +X).
// Other lights get a small marker.
#include <imgui.h>

#include "candela/render/frame_scene.h"

namespace candela::editor {

class EditorScene;

void drawLightGizmos(EditorScene& scene, const render::CameraView& camera, ImVec2 displaySize,
                     ImDrawList* drawList);

}  // namespace candela::editor
