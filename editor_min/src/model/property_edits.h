#pragma once
// Named property edits, for editor scripts and tests: `light.lumens 1600`,
// `transform.position 0 2 0`, `material.roughness 0.3` (primitive 0), `camera.aperture 8`.
// Each is one undoable command through the same paths the inspector uses.
#include <memory>
#include <string>
#include <vector>

#include "candela/ecs/entity.h"
#include "model/edit_command.h"

namespace candela::editor {

class EditorScene;

// The names property edits accept, for help text and error messages.
std::vector<std::string> editablePropertyNames();

// Builds the command setting `property` of `e` to `values`; null with `error` saying why (unknown
// property, wrong value count, the entity lacks the component, or a value the scene loader
// would reject: model/edit_validation.h). A value the loader would clamp is clamped, and
// `notice` (when given) says so.
std::unique_ptr<EditCommand> propertyEdit(EditorScene& scene, ecs::Entity e,
                                          const std::string& property,
                                          const std::vector<float>& values, std::string& error,
                                          std::string* notice = nullptr);

}  // namespace candela::editor
