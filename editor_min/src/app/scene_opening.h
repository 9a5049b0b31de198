#pragma once
// Opening a scene for editing: an engine scene file, or a glTF (which then gets a framing
// camera and lights when it has none, and saves as a scene file referencing it). Loading is
// runtime::loadScene, the same as `candela run`; this adds what editing needs.
#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "candela/runtime/scene_world.h"
#include "model/editor_scene.h"

namespace candela::editor {

struct OpenedScene {
    // Handed to the application, which then owns it; `scene` edits its registry.
    std::unique_ptr<runtime::SceneWorld> world;
    std::unique_ptr<EditorScene> scene;
    std::filesystem::path savePath;  // where Save writes: the scene file, or <glTF>.scene.json
    std::array<float, 4> background{0.05f, 0.05f, 0.05f, 1.0f};  // cd/m^2, as candela run
};

// Loads `path`; problems that do not stop loading are printed as warnings. nullopt with `error`
// naming the file when nothing usable could be read.
std::optional<OpenedScene> openScene(const std::filesystem::path& path, std::string& error);

// An empty scene (the editor started without one); saves to `untitled.scene.json`.
OpenedScene emptyScene();

}  // namespace candela::editor
