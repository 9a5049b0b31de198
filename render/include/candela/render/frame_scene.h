#pragma once
// What one frame draws, extracted from the ECS by the runtime: plain arrays the passes read.
#include <vulkan/vulkan.h>
#include <cstdint>

#include <glm/glm.hpp>
#include <optional>
#include <span>

#include "candela/content/components/atmosphere.h"
#include "candela/content/components/fog.h"
#include "candela/content/components/light.h"
#include "candela/content/hair.h"
#include "candela/content/material.h"
#include "candela/content/wire.h"

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
    // Skinned or morphed instances: this frame's deformed vertices (a DeformJob's target,
    // SceneResources::deformedVertexBuffer), a vertex buffer in the mesh's layout that every
    // geometry pass binds instead of the mesh's own (vertexBufferOf). Null: the mesh's.
    VkBuffer deformedVertices = VK_NULL_HANDLE;
    // Their deformed vertices of the previous frame, for the motion vectors (gbuffer.vert's
    // previous-position stream). Null: the same as this frame's (no deformation motion).
    VkBuffer previousDeformedVertices = VK_NULL_HANDLE;
    // Skinned draws: the deformed mesh's box this frame in mesh space (centre, half extent;
    // content::Skin's bounds), which shadow-caster fitting and sorting use instead of the
    // mesh's bind-pose box (SceneResources::meshSpaceBounds).
    bool ownBounds = false;
    glm::vec3 boundsCenter{0.0f};
    glm::vec3 boundsExtent{0.0f};
};

// One animated primitive's deformation this frame, run by the skinning compute pass before
// any geometry pass: mesh `mesh`'s bind-pose vertices, morphed by `morphWeightCount` weights
// from FrameScene::morphWeights[firstMorphWeight] and skinned by `jointCount` matrices from
// FrameScene::jointMatrices[firstJoint] (bind-pose mesh space to current mesh space, as
// content::Skin::jointMatrices), written into `target`. Counts of 0: no skinning / morphing.
struct DeformJob {
    uint32_t mesh = 0;
    VkBuffer target = VK_NULL_HANDLE;
    uint32_t firstJoint = 0;
    uint32_t jointCount = 0;
    uint32_t firstMorphWeight = 0;
    uint32_t morphWeightCount = 0;
};

// One wire (content/wire.h) at `world`, shaded with `material` (content::Material; null: the
// glTF default material). Both point into models that outlive the frame.
struct WireDraw {
    const content::Wire* wire = nullptr;
    const content::Material* material = nullptr;
    glm::mat4 world{1.0f};
};

// Hair strands (content/hair.h) at `world` in `style` (the material's extras.hair; null: not
// drawn). Both point into models (or scenes) that outlive the frame.
struct HairDraw {
    const content::Hair* hair = nullptr;
    const content::HairStyle* style = nullptr;
    glm::mat4 world{1.0f};
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
    // Animated draws: what the skinning pass writes this frame (empty: no pass at all).
    std::span<const DeformJob> deforms;
    std::span<const glm::mat4> jointMatrices;
    std::span<const float> morphWeights;
    std::span<const LightInstance> lights;
    // Wires (Persson 2014, GPU Pro 5, "Wire Antialiasing"): drawn by the wire pass after the lit
    // frame, not by the mesh passes.
    std::span<const WireDraw> wires;
    // Hair (Martin et al. 2014, GPU Pro 5, "TressFX: Advanced Real-Time Hair Rendering"): drawn by
    // the hair pass (an A-buffer) after the lit frame.
    std::span<const HairDraw> hair;
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
    // The participating medium (render/README.md "Volumetric lighting"), drawn in the mode
    // RendererOptions::volumetrics names; unset: clear air.
    std::optional<content::Fog> fog;
    // The physically based sky (render/README.md "Atmosphere"): set, it replaces the
    // environment for image-based lighting and the background; the first directional light in
    // `lights` is its sun.
    std::optional<content::Atmosphere> atmosphere;
};

}  // namespace candela::render
