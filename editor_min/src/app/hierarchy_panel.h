#pragma once
// The entity tree: click selects, drag an entity onto another to reparent it (or onto the
// empty area below the tree to make it a root), and buttons / context menu create, duplicate
// and delete. Structural edits are applied after the tree is drawn, never while iterating it.
#include <imgui.h>

#include <cstdint>
#include <unordered_map>

namespace candela::editor {

class EditorScene;

// Where each entity's row was drawn (screen pixels), for tests and tools that drive the panel.
struct HierarchyRow {
    ImVec2 min, max;
    ImVec2 center() const { return ImVec2((min.x + max.x) * 0.5f, (min.y + max.y) * 0.5f); }
};
using HierarchyLayout = std::unordered_map<uint64_t, HierarchyRow>;  // by EditorId

// `layout` (optional) receives the rows drawn this frame.
void drawHierarchyPanel(EditorScene& scene, HierarchyLayout* layout = nullptr);

}  // namespace candela::editor
