#pragma once
// Turns the `<scene>` argument into what the frame loop draws.
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <utility>
#include <vector>

#include "candela/render/frame_inputs.h"
#include "candela/runtime/application.h"
#include "candela/runtime/scene_world.h"

namespace candela::runtime {

struct LoadedScene {
    std::string name;
    render::FrameInputs frame;          // background; the test triangle for builtin:triangle
    std::unique_ptr<SceneWorld> world;  // entities to draw; null for builtin:triangle
    // The scene's own systems (animation, camera), run every frame in this order.
    std::vector<std::pair<std::string, System>> systems;
};

// Returns the scene, or nullopt with `error` naming the scene and the problem. Problems that
// do not stop loading (a skipped primitive, a missing texture) are printed as warnings.
// `externalSky`: the run lights the scene with a sky of its own (--env), so a glTF without
// lights gets no default sun and fill.
std::optional<LoadedScene> loadScene(const std::string& scene, std::string& error,
                                     bool externalSky = false);

}  // namespace candela::runtime
