#pragma once
// Turns the `<scene>` argument into what the frame loop draws.
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "candela/render/frame_inputs.h"
#include "candela/runtime/scene_world.h"

namespace candela::runtime {

struct LoadedScene {
    std::string name;
    render::FrameInputs frame;          // background; the test triangle for builtin:triangle
    std::unique_ptr<SceneWorld> world;  // entities to draw; null for builtin:triangle
    // Advances the scene's animation to a time in seconds (empty for static scenes).
    std::function<void(SceneWorld&, double)> animate;
};

// Returns the scene, or nullopt with `error` naming the scene and the problem. Problems that
// do not stop loading (a skipped primitive, a missing texture) are printed as warnings.
std::optional<LoadedScene> loadScene(const std::string& scene, std::string& error);

}  // namespace candela::runtime
