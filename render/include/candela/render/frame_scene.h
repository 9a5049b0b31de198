#pragma once
// What one frame draws, extracted from the ECS by the runtime: plain arrays the passes read.
#include <cstdint>
#include <vulkan/vulkan.h>

#include <glm/glm.hpp>
#include <span>

#include "candela/content/components/light.h"

namespace candela::render {

// Reverse-Z with an infinite far plane: depth = nearPlane / viewDistance, cleared to 0,
// tested GREATER_OR_EQUAL. Precision is best where it matters, and far needs no choosing.
struct CameraView {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::vec3 position{0.0f};
    float ev100 = 0.0f;
    float nearPlane = 0.05f;  // must match the projection's
    float farPlane = 500.0f;  // where the cluster grid's last depth slice begins
};

glm::mat4 reverseZPerspective(float verticalFov, float aspect, float nearPlane);

struct DrawItem {
    uint32_t mesh;      // from SceneResources
    uint32_t material;  // from SceneResources
    glm::mat4 world;
    // Skinned or morphed instances: this frame's deformed vertices (SceneResources::
    // writeDeformedVertices), a plain vertex buffer in the mesh's layout that every geometry
    // pass binds instead of the mesh's own (vertexBufferOf). Null: the mesh's vertices.
    VkBuffer deformedVertices = VK_NULL_HANDLE;
    // Their deformed vertices of the previous frame, for the motion vectors (gbuffer.vert's
    // previous-position stream). Null: the same as this frame's (no deformation motion).
    VkBuffer previousDeformedVertices = VK_NULL_HANDLE;
};

struct LightInstance {
    content::Light light;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // spot axis / directional travel (node -Z)
    glm::vec3 tubeAxis{1.0f, 0.0f, 0.0f};    // node +X
};

struct FrameScene {
    CameraView camera;
    std::span<const DrawItem> draws;
    // Motion vectors: each draw's world matrix in the previous frame, in the order of `draws`.
    // Empty (or another size): no draw moved by itself; camera motion is always accounted for.
    std::span<const glm::mat4> previousWorlds;
    std::span<const LightInstance> lights;
    // Light slots whose data changed since the previous frame. When lightsRestructured is set
    // (lights added or removed, or the caller does not track changes) every light is rewritten.
    std::span<const uint32_t> changedLights;
    bool lightsRestructured = true;
    // Multiplies the environment's radiance (SceneResources::environment()), for the sky
    // background and image-based lighting alike.
    float skyIntensity = 1.0f;
    // The scene's ambient occlusion reach (metres) and strength (0..1), when the renderer's
    // AoMode is on.
    float aoRadius = 1.5f;  // render/README.md "Ambient occlusion": why 1.5
    float aoIntensity = 1.0f;
};

}  // namespace candela::render
