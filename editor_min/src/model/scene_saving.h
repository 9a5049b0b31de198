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
// read-only target is refused unless `options.replaceReadOnly`. `brdf` is the scene-wide
// "brdf" setting (not an entity), kept as the opened file had it; `ambientOcclusion` the
// scene-wide "ambient_occlusion" (as opened, with the inspector's edits).
std::string saveEditedScene(ecs::Registry& registry, const std::filesystem::path& source,
                            const std::filesystem::path& target,
                            std::optional<content::SceneBrdf> brdf,
                            std::optional<content::SceneAmbientOcclusion> ambientOcclusion,
                            content::AtomicWriteOptions options = {});

}  // namespace candela::editor
