#pragma once
// Reads the ECS once per frame into the plain arrays the renderer draws: mesh draws, lights
// and the camera. The renderer never sees the registry.
#include <vector>

#include "candela/ecs/registry.h"
#include "candela/render/frame_scene.h"
#include "candela/render/scene_resources.h"
#include "light_table.h"

namespace candela::runtime {

struct ExtractedFrame {
    std::vector<render::DrawItem> draws;
    std::span<const render::LightInstance> lights;  // the light table's slots
    std::span<const uint32_t> changedLights;
    bool lightsRestructured = true;
    render::CameraView camera;
    bool hasCamera = false;  // false: no entity has Camera + WorldTransform
};

// Uploads models on first sight (SceneResources caches them); updates `lights`.
void extractFrame(ecs::Registry& registry, LightTable& lights, render::SceneResources& resources,
                  float aspect, ExtractedFrame& out);

}  // namespace candela::runtime
