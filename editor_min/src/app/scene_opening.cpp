#include "app/scene_opening.h"

#include "candela/content/components/mesh_instance.h"
#include "candela/runtime/scene_source.h"

namespace candela::editor {

namespace {

bool isGltf(const std::filesystem::path& path) {
    const std::string ext = path.extension().string();
    return ext == ".gltf" || ext == ".glb";
}

}  // namespace

std::optional<OpenedScene> openScene(const std::filesystem::path& path, std::string& error) {
    // What is there, said as it is: `open /dev/zero` answered "no such file" (issue 44).
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (!std::filesystem::exists(status)) {
        error = path.string() + ": no such file";
        return std::nullopt;
    }
    if (std::filesystem::is_directory(status)) {
        error = path.string() + ": is a directory, not a scene file";
        return std::nullopt;
    }
    if (!std::filesystem::is_regular_file(status)) {
        error = path.string() + ": not a regular file (a device, pipe or socket), not a scene file";
        return std::nullopt;
    }
    // The same loading as `candela run` (viewing defaults for a bare glTF, the background),
    // so the viewport shows what the runtime shows.
    std::optional<runtime::LoadedScene> loaded = runtime::loadScene(path.string(), error);
    if (!loaded) return std::nullopt;
    OpenedScene opened;
    opened.world = std::move(loaded->world);
    opened.background = loaded->frame.clearRadiance;
    if (isGltf(path)) {
        // Saved scenes reference the glTF by its file name, relative to the scene file.
        opened.world->registry.view<content::MeshInstance>().each(
            [&](content::MeshInstance& mesh) { mesh.gltfPath = path.filename().string(); });
        opened.savePath = path;
        opened.savePath.replace_extension(".scene.json");
    } else {
        opened.savePath = path;
    }
    opened.world->updateTransforms();
    opened.scene = std::make_unique<EditorScene>(opened.world->registry, path);
    opened.scene->setSceneRenderSettings(opened.world->sceneSettings());
    opened.scene->setSceneQuality(opened.world->sceneQuality());
    opened.scene->setSceneAmbientOcclusion(opened.world->sceneAmbientOcclusion());
    opened.scene->setSceneMaterialLayers(opened.world->sceneMaterialLayers());
    return opened;
}

OpenedScene emptyScene() {
    OpenedScene opened;
    opened.world = std::make_unique<runtime::SceneWorld>();
    opened.savePath = "untitled.scene.json";
    opened.scene = std::make_unique<EditorScene>(opened.world->registry, opened.savePath);
    return opened;
}

}  // namespace candela::editor
