#include "candela/runtime/frame_extraction.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <utility>

#include "candela/content/component_validation.h"
#include "candela/content/components/animation.h"
#include "candela/content/components/atmosphere.h"
#include "candela/content/components/camera.h"
#include "candela/content/components/fog.h"
#include "candela/content/components/hair_growth.h"
#include "candela/content/components/light.h"
#include "candela/content/components/mesh_instance.h"
#include "candela/content/components/scene_components.h"
#include "candela/content/components/sky.h"
#include "candela/ecs/transform.h"
#include "candela/render/exposure.h"
#include "candela/runtime/debug_text.h"

namespace candela::runtime {

namespace {

glm::mat4 toGlm(const ecs::Mat4& m) {
    glm::mat4 out;
    std::memcpy(&out[0][0], m.m, sizeof(m.m));  // both column-major
    return out;
}

glm::vec3 unitColumn(const glm::mat4& m, int column, const glm::vec3& fallback) {
    glm::vec3 v(m[column]);
    float length = glm::length(v);
    return length > 0.0f && std::isfinite(length) ? v / length : fallback;
}

bool isFinite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(m[c][r])) return false;
        }
    }
    return true;
}

// The entity's override materials, made (or remade after a change) on demand.
const ExtractedFrame::OverrideMaterials* overrideMaterials(ecs::Registry& registry, ecs::Entity e,
                                                           const content::Model& model,
                                                           render::SceneResources& resources,
                                                           ExtractedFrame& out) {
    const auto* component = registry.tryGet<content::MaterialOverrides>(e);
    if (!component || component->overrides.empty()) return nullptr;
    ExtractedFrame::OverrideMaterials& made = out.overrides[e.bits()];
    const ecs::Tick changed = registry.changeTick<content::MaterialOverrides>(e);
    if (made.builtAt != changed) {
        made.primitiveMaterial.clear();
        for (const content::MaterialOverride& o : component->overrides) {
            made.primitiveMaterial.emplace_back(o.primitive,
                                                resources.addMaterialOverride(model, o.material));
        }
        made.builtAt = changed;
    }
    return &made;
}

// An animated instance's skin and morph weights, packed into the frame's arrays once for all
// of its primitives. The bounds of a skin cover the deformed mesh (Skin::boundsMin/Max).
struct PackedPose {
    uint32_t firstJoint = 0, jointCount = 0, firstMorphWeight = 0, morphWeightCount = 0;
};

PackedPose packPose(const content::Skin* skin, const content::MorphWeights* morph,
                    ExtractedFrame& out) {
    PackedPose pose;
    if (skin && !skin->jointMatrices.empty()) {
        pose.firstJoint = uint32_t(out.jointMatrices.size());
        pose.jointCount = uint32_t(skin->jointMatrices.size());
        for (const ecs::Mat4& m : skin->jointMatrices)
            out.jointMatrices.push_back(toGlm(m));
    }
    if (morph && !morph->weights.empty()) {
        pose.firstMorphWeight = uint32_t(out.morphWeights.size());
        pose.morphWeightCount = uint32_t(morph->weights.size());
        out.morphWeights.insert(out.morphWeights.end(), morph->weights.begin(),
                                morph->weights.end());
    }
    return pose;
}

}  // namespace

void extractFrame(ecs::Registry& registry, LightTable& lights, render::SceneResources& resources,
                  float aspect, ExtractedFrame& out) {
    out.draws.clear();
    out.wires.clear();
    out.hair.clear();
    out.previousWorlds.clear();
    out.lastWorldNext.clear();
    out.deforms.clear();
    out.jointMatrices.clear();
    out.morphWeights.clear();
    // Buffers of instances no longer animated (destroyed, or their skin removed) go here: none
    // was drawn by the last frame, so no frame in flight uses them.
    resources.releaseUnusedDeformed();
    out.hasCamera = false;
    // Debug text is per frame: taken from the world, which starts the next frame empty.
    out.text.clear();
    if (DebugText* text = registry.resources().tryGet<DebugText>()) out.text.swap(text->lines);

    registry.view<const ecs::WorldTransform, const content::MeshInstance>().each(
        [&](ecs::Entity e, const ecs::WorldTransform& transform,
            const content::MeshInstance& instance) {
            if (!instance.model) return;
            glm::mat4 world = toGlm(transform.matrix);
            if (!isFinite(world)) return;  // a NaN transform hides the mesh, not the frame
            const render::UploadedModel& uploaded = resources.addModel(*instance.model);
            if (instance.mesh < 0 ||
                size_t(instance.mesh) >= uploaded.firstPrimitiveOfMesh.size()) {
                return;
            }
            const content::Model& model = *instance.model;
            for (const content::Wire& wire : model.meshes[size_t(instance.mesh)].wires) {
                const bool named =
                    wire.material >= 0 && size_t(wire.material) < model.materials.size();
                out.wires.push_back(
                    {&wire, named ? &model.materials[size_t(wire.material)] : nullptr, world});
            }
            if (const auto* growth = registry.tryGet<content::HairGrowth>(e)) {
                // Fur grown on the mesh (a scene file's "hair"): generated once per entity
                // and kept while its mesh and settings stay the same.
                const content::Mesh* mesh = &model.meshes[size_t(instance.mesh)];
                ExtractedFrame::GrownHair& grown = out.grownHair[e.bits()];
                if (grown.mesh != mesh || !(grown.growth == *growth)) {
                    grown.mesh = mesh;
                    grown.growth = *growth;
                    content::Primitive surface;
                    for (const content::Primitive& primitive : mesh->primitives) {
                        const auto base = uint32_t(surface.positions.size());
                        surface.positions.insert(surface.positions.end(),
                                                 primitive.positions.begin(),
                                                 primitive.positions.end());
                        surface.normals.insert(surface.normals.end(), primitive.normals.begin(),
                                               primitive.normals.end());
                        surface.normals.resize(surface.positions.size());
                        for (uint32_t index : primitive.indices)
                            surface.indices.push_back(base + index);
                    }
                    grown.hair =
                        content::generateHair(surface, growth->count, growth->length, growth->seed);
                }
                grown.seen = true;
                out.hair.push_back({&grown.hair, &grown.growth.style, world});
            }
            for (const content::Hair& hair : model.meshes[size_t(instance.mesh)].hair) {
                if (hair.material < 0 || size_t(hair.material) >= model.materials.size()) continue;
                const auto& style = model.materials[size_t(hair.material)].hair;
                if (style) out.hair.push_back({&hair, &*style, world});
            }
            uint32_t first = uploaded.firstPrimitiveOfMesh[instance.mesh];
            auto last = out.lastWorld.find(e.bits());
            const glm::mat4 previousWorld = last != out.lastWorld.end() ? last->second : world;
            out.lastWorldNext[e.bits()] = world;
            // Skinned or morphed: the skinning pass deforms the mesh into a per-instance buffer.
            const content::Skin* skin = registry.tryGet<content::Skin>(e);
            const content::MorphWeights* morph = registry.tryGet<content::MorphWeights>(e);
            const bool deform = skin != nullptr || morph != nullptr;
            const PackedPose pose = deform ? packPose(skin, morph, out) : PackedPose{};
            const ExtractedFrame::OverrideMaterials* overrides =
                overrideMaterials(registry, e, *instance.model, resources, out);
            for (uint32_t p = 0; p < uploaded.primitiveCountOfMesh[instance.mesh]; ++p) {
                uint32_t material = uint32_t(resources.mesh(first + p).defaultMaterial);
                if (overrides) {
                    for (auto [primitive, replaced] : overrides->primitiveMaterial) {
                        if (primitive == p) material = replaced;
                    }
                }
                out.draws.push_back({first + p, material, world});
                out.previousWorlds.push_back(previousWorld);
                if (deform && resources.mesh(first + p).deformable()) {
                    // This frame's buffer, and last frame's for the motion vectors when the
                    // instance was drawn then.
                    const render::SceneResources::DeformedVertices vertices =
                        resources.deformedVertexBuffers(e.bits() * 64 + p, first + p,
                                                        last != out.lastWorld.end());
                    render::DeformJob job{
                        first + p,       vertices.current,      pose.firstJoint,
                        pose.jointCount, pose.firstMorphWeight, pose.morphWeightCount};
                    render::DrawItem& draw = out.draws.back();
                    draw.deformedVertices = vertices.current;
                    draw.previousDeformedVertices = vertices.previous;
                    // The skin's box this frame: shadow fitting and sorting follow the pose.
                    if (skin && skin->boundsValid) {
                        const glm::vec3 lo(skin->boundsMin.x, skin->boundsMin.y, skin->boundsMin.z);
                        const glm::vec3 hi(skin->boundsMax.x, skin->boundsMax.y, skin->boundsMax.z);
                        draw.ownBounds = true;
                        draw.boundsCenter = 0.5f * (lo + hi);
                        draw.boundsExtent = 0.5f * (hi - lo);
                    }
                    out.deforms.push_back(job);
                }
            }
        });

    out.lastWorld.swap(out.lastWorldNext);
    // Fur of entities not drawn this frame (destroyed, hidden) is let go.
    for (auto it = out.grownHair.begin(); it != out.grownHair.end();) {
        if (it->second.seen) {
            it->second.seen = false;
            ++it;
        } else {
            it = out.grownHair.erase(it);
        }
    }

    lights.update();
    out.lights = lights.lights();
    out.changedLights = lights.changedSlots();
    out.lightsRestructured = lights.restructured();

    registry.view<const ecs::WorldTransform, const content::Camera>().each(
        [&](const ecs::WorldTransform& transform, const content::Camera& camera) {
            glm::mat4 world = toGlm(transform.matrix);
            if (out.hasCamera || !isFinite(world)) return;
            // The view ignores scale: only the camera's position and orientation count.
            glm::vec3 position(world[3]);
            glm::vec3 forward = -unitColumn(world, 2, {0.0f, 0.0f, 1.0f});
            glm::vec3 up = unitColumn(world, 1, {0.0f, 1.0f, 0.0f});
            out.camera.view = glm::lookAt(position, position + forward, up);
            out.camera.projection = render::reverseZPerspective(
                camera.verticalFov, aspect, camera.nearPlane > 0.0f ? camera.nearPlane : 0.05f);
            out.camera.position = position;
            out.camera.ev100 = render::ev100FromCamera(camera);
            out.camera.nearPlane = camera.nearPlane > 0.0f ? camera.nearPlane : 0.05f;
            out.camera.farPlane = std::max(camera.farPlane, out.camera.nearPlane * 2.0f);
            out.hasCamera = true;
        });

    // An absurd intensity (negative, NaN, Inf) would poison every pixel: it turns the sky off.
    out.skyIntensity = 1.0f;
    out.skyExrPath.clear();
    registry.view<const content::Sky>().each([&](const content::Sky& sky) {
        out.skyExrPath = sky.exrPath;
        out.skyIntensity =
            std::isfinite(sky.intensity) && sky.intensity >= 0.0f ? sky.intensity : 0.0f;
    });
    // A medium the loader's rules reject (code may emplace any values) draws no fog.
    out.fog.reset();
    registry.view<const content::Fog>().each([&](const content::Fog& fog) {
        content::Fog checked = fog;
        if (!content::anyRejected(content::validateFog(checked))) out.fog = checked;
    });
    out.atmosphere.reset();
    registry.view<const content::Atmosphere>().each([&](const content::Atmosphere& atmosphere) {
        content::Atmosphere checked = atmosphere;
        if (!content::anyRejected(content::validateAtmosphere(checked))) out.atmosphere = checked;
    });
}

}  // namespace candela::runtime
