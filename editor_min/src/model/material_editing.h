#pragma once
// Materials as the inspector edits them: a mesh entity's primitive draws either its model's
// material or a scene-file MaterialOverride; an edit writes an override (the renderer remakes
// override materials when MaterialOverrides changes, see runtime frame extraction).
#include <cstdint>
#include <memory>

#include "candela/content/material.h"
#include "candela/ecs/entity.h"
#include "model/edit_command.h"

namespace candela::editor {

class EditorScene;

// Number of primitives of the entity's mesh (0 without a loaded MeshInstance).
uint32_t primitiveCount(EditorScene& scene, ecs::Entity e);
// What primitive `primitive` of `e` is drawn with now.
content::Material effectiveMaterial(EditorScene& scene, ecs::Entity e, uint32_t primitive);
// The command making `material` primitive `primitive`'s override.
std::unique_ptr<EditCommand> setMaterial(EditorScene& scene, ecs::Entity e, uint32_t primitive,
                                         const content::Material& material);

}  // namespace candela::editor
