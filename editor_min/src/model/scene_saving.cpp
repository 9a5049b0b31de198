#include "model/scene_saving.h"

#include <system_error>

#include "candela/content/scene_instantiation.h"

namespace candela::editor {

namespace {

std::filesystem::path absoluteDirectory(const std::filesystem::path& file) {
    std::error_code ec;
    std::filesystem::path dir = std::filesystem::absolute(file, ec).parent_path();
    return dir.lexically_normal();
}

// `stored` was relative to `from`; returns it relative to `to` (absolute paths are kept).
std::string rebase(const std::string& stored, const std::filesystem::path& from,
                   const std::filesystem::path& to) {
    const std::filesystem::path path(stored);
    if (stored.empty() || path.is_absolute() || from == to) return stored;
    const std::filesystem::path target = (from / path).lexically_normal();
    std::filesystem::path relative = target.lexically_relative(to);
    return relative.empty() ? target.string() : relative.generic_string();
}

}  // namespace

content::SceneDocument documentForSaving(ecs::Registry& registry,
                                         const std::filesystem::path& source,
                                         const std::filesystem::path& target) {
    content::SceneDocument document = content::captureScene(registry);
    const std::filesystem::path from = absoluteDirectory(source);
    const std::filesystem::path to = absoluteDirectory(target);
    for (content::SceneEntity& entity : document.entities) {
        if (entity.mesh && entity.mesh->builtin.empty()) {
            entity.mesh->gltfPath = rebase(entity.mesh->gltfPath, from, to);
        }
        if (entity.model) entity.model->gltfPath = rebase(entity.model->gltfPath, from, to);
        if (entity.sky) entity.sky->exrPath = rebase(entity.sky->exrPath, from, to);
    }
    return document;
}

std::string saveEditedScene(ecs::Registry& registry, const std::filesystem::path& source,
                            const std::filesystem::path& target,
                            const content::SceneDocument& settings,
                            content::AtomicWriteOptions options) {
    content::SceneDocument document = documentForSaving(registry, source, target);
    document.settings = settings.settings;
    document.quality = settings.quality;
    document.ambientOcclusion = settings.ambientOcclusion;
    document.materialLayers = settings.materialLayers;
    return content::saveSceneFile(target, document, options);
}

}  // namespace candela::editor
