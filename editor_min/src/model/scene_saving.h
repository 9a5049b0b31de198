#pragma once
// Saving the edited registry as an engine scene file.
#include <filesystem>
#include <optional>
#include <string>

#include "candela/content/scene_file.h"
#include "candela/ecs/registry.h"

namespace candela::editor {

// Every SceneMember entity (content::captureScene) with its asset paths made valid for a file at
// `target`: paths stored relative to `source`'s directory are rewritten relative to `target`'s.
content::SceneDocument documentForSaving(ecs::Registry& registry,
                                         const std::filesystem::path& source,
                                         const std::filesystem::path& target);

// Atomic save (content::saveSceneFile). Empty on success, else the error naming the file. A
// read-only target is refused unless `options.replaceReadOnly`. The scene-wide
// "brdf", "aa", "bloom", "exposure", "exposure_compensation" and "ambient_occlusion" settings
// come from `settings` (every field but its entities): they are not entities, so the registry
// does not hold them; the editor keeps them as the opened file had them, with its edits.
std::string saveEditedScene(ecs::Registry& registry, const std::filesystem::path& source,
                            const std::filesystem::path& target,
                            const content::SceneDocument& settings,
                            content::AtomicWriteOptions options = {});

}  // namespace candela::editor
