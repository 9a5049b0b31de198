#include "candela/content/model_instantiation.h"

#include <candela/ecs/hierarchy.h>
#include <candela/ecs/registry.h>
#include <candela/ecs/transform.h>

#include "candela/content/animation_systems.h"
#include "candela/content/components/animation.h"
#include "candela/content/components/mesh_instance.h"
#include "candela/content/components/name.h"
#include "local_transform.h"

namespace candela::content {

namespace {

// Skins and morph weights on the mesh entities, and one AnimationPlayer (first clip, looping)
// on the first root when the model has clips.
void addAnimationComponents(ecs::Registry& registry, const Model& model,
                            const std::vector<ecs::Entity>& nodeEntities,
                            const std::vector<ecs::Entity>& created) {
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        const Node& node = model.nodes[n];
        const ecs::Entity e = nodeEntities[n];
        if (e == ecs::kNullEntity || node.mesh == kNoIndex) continue;
        if (node.skin != kNoIndex) {
            Skin skin;
            skin.model = &model;
            skin.skin = node.skin;
            for (std::int32_t joint : model.skins[static_cast<std::size_t>(node.skin)].joints)
                skin.joints.push_back(nodeEntities[static_cast<std::size_t>(joint)]);
            skin.jointMatrices.assign(skin.joints.size(), ecs::Mat4::identity());
            computeJointBounds(model, node.mesh, skin);
            registry.emplace<Skin>(e, std::move(skin));
        }
        const Mesh& mesh = model.meshes[static_cast<std::size_t>(node.mesh)];
        if (!mesh.defaultWeights.empty()) {
            MorphWeights morph;
            morph.weights = node.weights.size() == mesh.defaultWeights.size() ? node.weights
                                                                              : mesh.defaultWeights;
            registry.emplace<MorphWeights>(e, std::move(morph));
        }
    }
    if (!model.animations.empty() && !created.empty()) {
        AnimationPlayer player;
        player.model = &model;
        player.clip = 0;
        player.nodeEntities = nodeEntities;
        registry.emplace<AnimationPlayer>(created.front(), std::move(player));
    }
}

}  // namespace

std::vector<ecs::Entity> instantiateModel(ecs::Registry& registry, const Model& model,
                                          ecs::Entity parent, const std::string& gltfPath) {
    std::vector<ecs::Entity> created;
    // Depth-first from the shown roots; an explicit stack, because glTF trees can be deep.
    std::vector<std::pair<std::int32_t, ecs::Entity>> pending;
    for (auto it = model.rootNodes.rbegin(); it != model.rootNodes.rend(); ++it) {
        pending.emplace_back(*it, parent);
    }
    std::vector<bool> visited(model.nodes.size(), false);
    std::vector<ecs::Entity> nodeEntities(model.nodes.size(), ecs::kNullEntity);
    while (!pending.empty()) {
        auto [nodeIndex, parentEntity] = pending.back();
        pending.pop_back();
        // The loader validated indices; a node reached twice (shared child) is shown once.
        if (nodeIndex < 0 || size_t(nodeIndex) >= model.nodes.size() || visited[nodeIndex]) {
            continue;
        }
        visited[nodeIndex] = true;
        const Node& node = model.nodes[nodeIndex];
        ecs::Entity e = registry.create();
        registry.emplace<Name>(e, Name{node.name});
        registry.emplace<ecs::LocalTransform>(e, toLocalTransform(node.local));
        registry.emplace<ecs::WorldTransform>(e);
        if (parentEntity != ecs::kNullEntity) (void)ecs::setParent(registry, e, parentEntity);
        if (node.mesh >= 0 && size_t(node.mesh) < model.meshes.size()) {
            registry.emplace<MeshInstance>(e, MeshInstance{&model, node.mesh, gltfPath});
        }
        if (node.light >= 0 && size_t(node.light) < model.lights.size()) {
            registry.emplace<Light>(e, model.lights[node.light].light);
        }
        if (node.camera >= 0 && size_t(node.camera) < model.cameras.size()) {
            registry.emplace<Camera>(e, model.cameras[node.camera].camera);
        }
        if (node.rigidBody) registry.emplace<RigidBody>(e, *node.rigidBody);
        if (node.collider) registry.emplace<Collider>(e, *node.collider);
        created.push_back(e);
        nodeEntities[static_cast<std::size_t>(nodeIndex)] = e;
        for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) {
            pending.emplace_back(*it, e);
        }
    }
    addAnimationComponents(registry, model, nodeEntities, created);
    return created;
}

}  // namespace candela::content
