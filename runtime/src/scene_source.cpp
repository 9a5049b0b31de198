#include "scene_source.h"

#include <filesystem>

namespace candela::runtime {

namespace {

// The foundation test scene: a flat HDR triangle over a dim clear colour, at EV100 0.
LoadedScene builtinTriangle() {
    LoadedScene scene;
    scene.name = "builtin:triangle";
    scene.frame.scene.camera.ev100 = 0.0f;
    scene.frame.clearRadiance = {0.05f, 0.1f, 0.2f, 1.0f};
    scene.frame.testTriangleRadiance = {2.0f, 0.5f, 0.125f, 1.0f};
    return scene;
}

}  // namespace

std::optional<LoadedScene> loadScene(const std::string& scene, std::string& error) {
    if (scene.empty()) {
        error = "no scene given";
        return std::nullopt;
    }
    if (scene == "builtin:triangle") return builtinTriangle();
    if (scene.rfind("builtin:", 0) == 0) {
        error = "unknown built-in scene '" + scene + "' (available: builtin:triangle)";
        return std::nullopt;
    }
    std::error_code ec;
    if (!std::filesystem::is_regular_file(scene, ec)) {
        error = "scene file '" + scene + "' does not exist or is not a file";
        return std::nullopt;
    }
    error = "scene file '" + scene + "': loading scene files into the renderer is not wired up yet";
    return std::nullopt;
}

}  // namespace candela::runtime
