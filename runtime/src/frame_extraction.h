#pragma once
// Reads the ECS once per frame into the plain arrays the renderer draws: mesh draws, lights
// and the camera. The renderer never sees the registry.
#include <vector>

#include "candela/ecs/registry.h"
#include "candela/render/frame_scene.h"
#include "candela/render/scene_resources.h"

namespace candela::runtime {

struct ExtractedFrame {
    std::vector<render::DrawItem> draws;
    std::vector<render::LightInstance> lights;
    render::CameraView camera;
    bool hasCamera = false;  // false: no entity has Camera + WorldTransform
};

// Uploads models on first sight (SceneResources caches them).
void extractFrame(ecs::Registry& registry, render::SceneResources& resources, float aspect,
                  ExtractedFrame& out);

}  // namespace candela::runtime
