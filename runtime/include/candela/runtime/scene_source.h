#pragma once
// Turns a `<scene>` argument (a scene file, a glTF, builtin:demo, builtin:triangle) into what
// the frame loop draws: the one place `candela run` and the editor open scenes. Engine-side
// (render types): games load their levels through SceneWorld instead.
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
    // Adds the scene's own systems (animation, camera) to an application; null: none.
    std::function<void(Application&)> addSystems;
};

// Returns the scene, or nullopt with `error` naming the scene and the problem. Problems that
// do not stop loading (a skipped primitive, a missing texture) are printed as warnings.
// `externalSky`: the run lights the scene with a sky of its own (--env), so a glTF without
// lights gets no default sun and fill.
std::optional<LoadedScene> loadScene(const std::string& scene, std::string& error,
                                     bool externalSky = false);

}  // namespace candela::runtime
