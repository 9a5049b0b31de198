// Scene file I/O: bounded reads and atomic saves around the JSON reader/writer.
#include "candela/content/scene_file.h"
#include "atomic_file_write.h"
#include "file_bytes.h"

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

std::string saveSceneFile(const std::filesystem::path& path, const SceneDocument& scene) {
    std::string error;
    const std::string text = sceneToJson(scene, error);
    if (!error.empty()) return path.string() + ": " + error;
    return writeFileAtomically(path, text);
}

}  // namespace candela::content
