#pragma once
// The skeleton pass: one linear walk over a player's model nodes, parents first, that writes
// the sampled pose to the node entities, composes each node's world matrix from its parent's
// (the local-to-model step) and builds the player's skins from those matrices, so an animated
// character needs neither transform propagation nor a second pass over its joints.
//
// Joints that nothing else reads (no mesh, light or camera, nothing attached) get their
// LocalTransform written without a change stamp and their WorldTransform written directly:
// propagation then has nothing to redo for them, and still recomputes them (from the written
// locals) whenever an ancestor moves. Where the entities no longer mirror the model's
// hierarchy (a node reparented, a transform removed) the pass falls back to writing stamped
// locals only, and propagation and updateSkins do the rest as for any entity.
#include <cstdint>

#include "candela/content/components/animation.h"
#include "candela/ecs/component_pool.h"
#include "candela/ecs/registry.h"

namespace candela::content {

// AnimationPlayer::Scratch::touched bits.
constexpr std::uint8_t kTransformTouched = 1;
constexpr std::uint8_t kWeightsTouched = 2;

// The LocalTransform and WorldTransform pools, fetched once per frame (null: none exists).
struct TransformPools {
    ecs::ComponentPool* locals = nullptr;
    ecs::ComponentPool* worlds = nullptr;
};

// Writes player.scratch.pose (the nodes marked kTransformTouched; the others keep their
// entity's own LocalTransform) as described above. Safe to run for different players in
// parallel; allocates nothing once bound.
void writeSkeletonPose(ecs::Registry& registry, const TransformPools& pools,
                       AnimationPlayer& player);

}  // namespace candela::content
