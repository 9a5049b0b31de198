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
    const std::string text = sceneToJson(scene, error);
    if (!error.empty()) return path.string() + ": " + error;
    return writeFileAtomically(path, text, options);
}

}  // namespace candela::content
