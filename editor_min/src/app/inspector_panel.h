#pragma once
// The inspector: every component of the selected entity as widgets. Each change becomes an
// undoable command (a drag is one undo step); the registry write marks the component changed,
// so the viewport shows the edit on the next frame.
#include <imgui.h>

#include <cstdint>
#include <string>
#include <unordered_map>

#include "candela/ecs/transform_math.h"

namespace candela::editor {

class EditorScene;

// Where each editing widget was drawn, by its command label ("Set Lumens"), for tests and
// tools that drive the panel.
struct InspectorWidget {
    ImVec2 min, max;
    ImVec2 center() const { return ImVec2((min.x + max.x) * 0.5f, (min.y + max.y) * 0.5f); }
};
using InspectorLayout = std::unordered_map<std::string, InspectorWidget>;

struct InspectorState {
    InspectorLayout* layout = nullptr;  // optional: receives this frame's widgets

    // Euler angles shown for the selected entity's rotation, kept while they still produce the
    // stored quaternion, so a drag does not jump between equivalent angle triples.
    uint64_t eulerEntity = 0;
    ecs::Quat eulerSource{};
    float eulerDegrees[3] = {0, 0, 0};
};

void drawInspectorPanel(EditorScene& scene, InspectorState& state);

}  // namespace candela::editor
