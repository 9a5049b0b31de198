#pragma once
// The sky a frame is lit by, loaded into the scene resources when it changes: the file given on
// the command line (`--env`) if any, else the world's Sky component. `candela run` and the
// editor both use it, so a scene is lit the same in both. A file that cannot be used gives its
// messages and the neutral sky (render::Environment::load).
#include <filesystem>
#include <optional>

namespace candela::render {
class FrameSubmitter;
class GpuContext;
class SceneResources;
}  // namespace candela::render

namespace candela::runtime {

class SceneWorld;
struct ExtractedFrame;

class SkyLoader {
public:
    explicit SkyLoader(std::optional<std::filesystem::path> override = std::nullopt)
        : override_(std::move(override)) {}

    // True when the sky changed (loaded, replaced or removed). Waits for the submitter first:
    // the previous sky may still be read by the last frame. Messages go to stderr after
    // `program: `.
    bool update(const SceneWorld& world, const ExtractedFrame& frame, render::GpuContext& context,
                render::FrameSubmitter& submitter, render::SceneResources& resources,
                const char* program);

private:
    std::optional<std::filesystem::path> override_;
    std::optional<std::filesystem::path> current_;  // what resources' environment came from
};

}  // namespace candela::runtime
