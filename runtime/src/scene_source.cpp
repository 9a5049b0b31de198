#include "candela/runtime/scene_source.h"

#include <cstdio>
#include <filesystem>

#include "demo_scene.h"

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

// Daylight sky behind glTF scenes, in cd/m^2 (about 0.2 after sunny-16 exposure).
constexpr std::array<float, 4> kSkyRadiance = {3000.0f, 4500.0f, 7000.0f, 1.0f};
constexpr std::array<float, 4> kSceneFileBackgroundRadiance = {0.05f, 0.05f, 0.05f, 1.0f};

void printDiagnostics(const content::Diagnostics& diagnostics) {
    for (const content::Diagnostic& d : diagnostics.messages) {
        std::fprintf(stderr, "candela: %s\n", content::formatDiagnostic(d).c_str());
    }
}

}  // namespace

std::optional<LoadedScene> loadScene(const std::string& scene, std::string& error,
                                     bool externalSky) {
    if (scene.empty()) {
        error = "no scene given";
        return std::nullopt;
    }
    if (scene == "builtin:triangle") return builtinTriangle();
    if (scene == "builtin:demo") {
        LoadedScene loaded;
        loaded.name = scene;
        loaded.world = std::make_unique<SceneWorld>();
        content::Diagnostics diagnostics;
        buildDemoScene(*loaded.world, diagnostics);
        loaded.addSystems = addDemoSystems;
        printDiagnostics(diagnostics);
        loaded.frame.clearRadiance = kDemoBackgroundRadiance;
        return loaded;
    }
    if (scene.rfind("builtin:", 0) == 0) {
        error =
            "unknown built-in scene '" + scene + "' (available: builtin:triangle, builtin:demo)";
        return std::nullopt;
    }
    std::error_code ec;
    if (!std::filesystem::is_regular_file(scene, ec)) {
        error = "scene file '" + scene + "' does not exist or is not a file";
        return std::nullopt;
    }
    std::string ext = std::filesystem::path(scene).extension().string();
    const bool sceneFile = ext == ".json";
    if (ext != ".gltf" && ext != ".glb" && !sceneFile) {
        error = "scene file '" + scene + "': unsupported type '" + ext +
                "' (use an engine scene .json, .gltf or .glb)";
        return std::nullopt;
    }
    LoadedScene loaded;
    loaded.name = scene;
    loaded.world = std::make_unique<SceneWorld>();
    content::Diagnostics diagnostics;
    bool ok = sceneFile ? loaded.world->loadSceneFile(scene, diagnostics)
                        : loaded.world->loadGltf(scene, diagnostics);
    printDiagnostics(diagnostics);
    if (!ok) {
        error = "scene file '" + scene + "' could not be loaded (see the messages above)";
        return std::nullopt;
    }
    if (sceneFile) {
        // Engine scenes light themselves; until skies render, the background is a dim neutral.
        loaded.frame.clearRadiance = kSceneFileBackgroundRadiance;
    } else {
        for (const std::string& added : loaded.world->addViewingDefaults(externalSky)) {
            std::fprintf(stderr, "candela: %s: %s\n", scene.c_str(), added.c_str());
        }
        loaded.frame.clearRadiance = kSkyRadiance;
    }
    return loaded;
}

}  // namespace candela::runtime
