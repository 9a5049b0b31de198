#pragma once
// The entity tree: click selects, drag an entity onto another to reparent it (or onto the
// empty area below the tree to make it a root), and buttons / context menu create, duplicate
// and delete. Structural edits are applied after the tree is drawn, never while iterating it.
namespace candela::editor {

class EditorScene;

void drawHierarchyPanel(EditorScene& scene);

}  // namespace candela::editor
