// Scene file I/O: bounded reads and atomic saves around the JSON reader/writer.
#include "candela/content/scene_file.h"
#include "candela/content/atomic_file_write.h"
#include "candela/content/file_bytes.h"

namespace candela::content {

namespace {
constexpr std::uint64_t kMaxSceneFileBytes = 256ull * 1024 * 1024;
}

std::optional<SceneDocument> loadSceneFile(const std::filesystem::path& path,
                                           Diagnostics& diagnostics) {
    FileBytes file = readFileBytes(path, kMaxSceneFileBytes);
    if (!file.error.empty()) {
        diagnostics.error(path.string(), "", file.error);
        return std::nullopt;
    }
    return parseSceneJson(file.bytes, path.string(), diagnostics);
}

std::string saveSceneFile(const std::filesystem::path& path, const SceneDocument& scene,
                          AtomicWriteOptions options) {
    std::string error;
    // Clips resolved when the scene was instantiated (absolute) go back relative to the file.
    SceneDocument relative = scene;
    const std::filesystem::path directory =
        std::filesystem::absolute(path).parent_path().lexically_normal();
    for (SceneEntity& e : relative.entities) {
        if (!e.audioSource) continue;
        const std::filesystem::path clip(e.audioSource->clip);
        if (clip.is_absolute())
            e.audioSource->clip = clip.lexically_normal().lexically_relative(directory).string();
    }
    const std::string text = sceneToJson(relative, error);
    if (!error.empty()) return path.string() + ": " + error;
    return writeFileAtomically(path, text, options);
}

}  // namespace candela::content
