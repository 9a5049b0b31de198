#pragma once
#include <optional>
#include <string>
// Reads the ECS once per frame into the plain arrays the renderer draws: mesh draws, lights
// and the camera. The renderer never sees the registry.
#include <unordered_map>
#include <utility>
#include <vector>

#include "candela/content/components/hair_growth.h"
#include "candela/content/model.h"
#include "candela/ecs/registry.h"
#include "candela/render/frame_scene.h"
#include "candela/render/scene_resources.h"
#include "candela/render/text_overlay.h"
#include "candela/runtime/light_table.h"

namespace candela::runtime {

struct ExtractedFrame {
    std::vector<render::DrawItem> draws;
    // Motion vectors: each draw's world matrix in the previous frame (its current one when the
    // entity is new), parallel to `draws`; kept per entity between frames.
    std::vector<glm::mat4> previousWorlds;
    // The mesh instances' wires (content::Mesh::wires), drawn by the wire pass.
    std::vector<render::WireDraw> wires;
    // The mesh instances' hair (content::Mesh::hair), drawn by the hair pass.
    std::vector<render::HairDraw> hair;
    // Fur grown on entities' meshes (content::HairGrowth), per entity: what `hair` points to.
    struct GrownHair {
        const content::Mesh* mesh = nullptr;
        content::HairGrowth growth;
        content::Hair hair;
        bool seen = false;  // drawn this frame; others are dropped after extraction
    };
    std::unordered_map<uint64_t, GrownHair> grownHair;
    std::unordered_map<uint64_t, glm::mat4> lastWorld;      // per entity, last frame
    std::unordered_map<uint64_t, glm::mat4> lastWorldNext;  // being filled this frame
    std::span<const render::LightInstance> lights;          // the light table's slots
    std::span<const uint32_t> changedLights;
    bool lightsRestructured = true;
    render::CameraView camera;
    bool hasCamera = false;              // false: no entity has Camera + WorldTransform
    float skyIntensity = 1.0f;           // the Sky component's
    std::string skyExrPath;              // the Sky component's file as stored (empty: no sky)
    std::optional<content::Fog> fog;     // a Fog component's medium (the last one seen)
    std::vector<render::TextLine> text;  // the frame's DebugText lines (debug_text.h)

    // An Atmosphere component's sky (the last one seen), checked by validateAtmosphere.
    std::optional<content::Atmosphere> atmosphere;

    // GPU materials made for scene-file material overrides, per entity; remade when the
    // entity's MaterialOverrides change.
    struct OverrideMaterials {
        ecs::Tick builtAt = 0;
        std::vector<std::pair<uint32_t, uint32_t>> primitiveMaterial;  // primitive, material
    };
    std::unordered_map<uint64_t, OverrideMaterials> overrides;
    // Animated draws (skins, morph targets): what the skinning pass deforms this frame, and
    // the joint matrices and morph weights of every animated instance, packed.
    std::vector<render::DeformJob> deforms;
    std::vector<glm::mat4> jointMatrices;
    std::vector<float> morphWeights;
};

// Uploads models on first sight (SceneResources caches them); updates `lights`.
void extractFrame(ecs::Registry& registry, LightTable& lights, render::SceneResources& resources,
                  float aspect, ExtractedFrame& out);

}  // namespace candela::runtime
