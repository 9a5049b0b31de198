#pragma once
// Turns the `<scene>` argument into what the renderer draws.
#include <optional>
#include <string>

#include "candela/render/frame_inputs.h"

namespace candela::runtime {

struct LoadedScene {
    std::string name;
    render::FrameInputs frame;
};

// Returns the scene, or nullopt with `error` naming the scene and the problem.
std::optional<LoadedScene> loadScene(const std::string& scene, std::string& error);

}  // namespace candela::runtime
