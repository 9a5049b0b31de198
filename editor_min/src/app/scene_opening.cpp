#include "app/scene_opening.h"

#include <cstdio>

#include "candela/content/components/mesh_instance.h"
#include "candela/content/diagnostics.h"

namespace candela::editor {

namespace {

// A glTF shown on its own gets a bright sky behind it, as `candela run` does.
constexpr std::array<float, 4> kSkyRadiance = {3000.0f, 4500.0f, 7000.0f, 1.0f};

bool isGltf(const std::filesystem::path& path) {
    const std::string ext = path.extension().string();
    return ext == ".gltf" || ext == ".glb";
}

}  // namespace

std::optional<OpenedScene> openScene(const std::filesystem::path& path, std::string& error) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        error = path.string() + ": no such file";
        return std::nullopt;
    }
    OpenedScene opened;
    opened.world = std::make_unique<runtime::SceneWorld>();
    content::Diagnostics diagnostics;
    const bool gltf = isGltf(path);
    const bool ok = gltf ? opened.world->loadGltf(path, diagnostics)
                         : opened.world->loadSceneFile(path, diagnostics);
    for (const content::Diagnostic& d : diagnostics.messages) {
        std::fprintf(stderr, "candela-editor: %s\n", content::formatDiagnostic(d).c_str());
    }
    if (!ok) {
        error = path.string() + ": could not be loaded (see the messages above)";
        return std::nullopt;
    }
    if (gltf) {
        // Saved scenes reference the glTF by its file name, relative to the scene file.
        opened.world->registry.view<content::MeshInstance>().each(
            [&](content::MeshInstance& mesh) { mesh.gltfPath = path.filename().string(); });
        for (const std::string& added : opened.world->addViewingDefaults()) {
            std::fprintf(stderr, "candela-editor: %s: %s\n", path.c_str(), added.c_str());
        }
        opened.background = kSkyRadiance;
        opened.savePath = path;
        opened.savePath.replace_extension(".scene.json");
    } else {
        opened.savePath = path;
    }
    opened.world->updateTransforms();
    opened.scene = std::make_unique<EditorScene>(opened.world->registry, path);
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
