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
#include <cstddef>
#include <cstdint>

#include "candela/content/components/animation.h"
#include "candela/ecs/component_pool.h"
#include "candela/ecs/registry.h"

namespace candela::content {

// Per model node, which of its properties this frame's clips animate (`touched`) bits.
constexpr std::uint8_t kTransformTouched = 1;
constexpr std::uint8_t kWeightsTouched = 2;
// Models up to this many nodes keep those flags in a per-thread buffer; larger ones in
// AnimationPlayer::Scratch::touched.
constexpr std::size_t kThreadTouchedNodes = 256;

// The LocalTransform and WorldTransform pools, fetched once per frame (null: none exists).
// The Skin pool rides along: the pass builds its player's skins. So does the hierarchy's
// version (ecs::hierarchyVersion, a resource lookup: once per frame, not once per player;
// nothing in the player loop reparents).
struct TransformPools {
    ecs::ComponentPool* locals = nullptr;
    ecs::ComponentPool* worlds = nullptr;
    ecs::ComponentPool* skins = nullptr;
    std::uint64_t hierarchyVersion = 0;
};

// Binds the pass to the registry if anything changed since (no allocation once bound) and
// says whether it will write worlds itself: then the sampler may write the pose straight into
// the node entities' LocalTransform (Scratch::localIndex; kAbsent: player.scratch.pose).
bool prepareSkeletonPose(ecs::Registry& registry, const TransformPools& pools,
                         AnimationPlayer& player);

// Writes the pose (the nodes `touched` marks kTransformTouched; the others keep their entity's own
// LocalTransform) as described above: from player.scratch.pose, or, with poseInLocals, already
// in the node entities' LocalTransform where they have one (only after prepareSkeletonPose
// returned true this frame, whose binding check is then not repeated). Safe to run for
// different players in parallel; allocates nothing once bound.
void writeSkeletonPose(ecs::Registry& registry, const TransformPools& pools,
                       AnimationPlayer& player, const std::uint8_t* touched, bool poseInLocals);

// Asks the memory system for what writeSkeletonPose(player) will touch (its scratch and its
// entities' transforms; a bound player only): a player's data lies in a dozen separate blocks
// that the hardware prefetcher cannot guess, so the caller issues this one player ahead and the
// misses overlap the current player's work. Reads only `player` and its own scratch.
void prefetchSkeletonPose(const TransformPools& pools, const AnimationPlayer& player);
// The first step of that, issued two players ahead: the player's own record (which holds the
// addresses prefetchSkeletonPose reads).
void prefetchPlayerRecord(const AnimationPlayer& player);
// (Not the joint matrices the skins receive: prefetching them as the player starts
// sampling was measured 3 to 4 % slower at 10,000 Foxes, its 24 lines per player contending
// for the miss buffers with the lines the walk waits on.)

}  // namespace candela::content
