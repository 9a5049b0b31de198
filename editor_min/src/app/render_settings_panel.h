#pragma once
// The scene file's render settings as widgets, one per row of content/render_setting_table.h:
// each can be left to the quality preset or chosen. Drawn by the inspector when nothing is
// selected.
#include "app/inspector_panel.h"

namespace candela::editor {

// `layout` (optional) receives each widget by its row's stats name ("ssr", "bloom").
void drawSceneRenderSettings(EditorScene& scene, InspectorLayout* layout);

}  // namespace candela::editor
