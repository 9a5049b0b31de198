#pragma once
// The inspector: every component of the selected entity as widgets. Each change becomes an
// undoable command (a drag is one undo step); the registry write marks the component changed,
// so the viewport shows the edit on the next frame.
#include <cstdint>

#include "candela/ecs/transform_math.h"

namespace candela::editor {

class EditorScene;

struct InspectorState {
    // Euler angles shown for the selected entity's rotation, kept while they still produce the
    // stored quaternion, so a drag does not jump between equivalent angle triples.
    uint64_t eulerEntity = 0;
    ecs::Quat eulerSource{};
    float eulerDegrees[3] = {0, 0, 0};
};

void drawInspectorPanel(EditorScene& scene, InspectorState& state);

}  // namespace candela::editor
