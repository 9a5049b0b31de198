#pragma once
// The animation systems: sample and blend each AnimationPlayer's clips into its nodes'
// LocalTransform and MorphWeights (before transform propagation), then rebuild each Skin's
// joint matrices and bounds from the propagated WorldTransforms. Both run in parallel over
// entities on the job system and allocate nothing per frame once each player and skin has
// run once.
//
//   addAnimationSystems(scheduler, [&] { return deltaSeconds; });  // after addTransformSystem
#include <functional>

#include "candela/content/components/animation.h"
#include "candela/content/model.h"
#include "candela/ecs/job_system.h"
#include "candela/ecs/registry.h"
#include "candela/ecs/scheduler.h"

namespace candela::content {

// Advances every playing AnimationPlayer by deltaSeconds * speed and writes the sampled (and
// crossfaded) pose to its nodes' LocalTransform (markChanged) and MorphWeights.
void advanceAnimationPlayers(ecs::Registry& registry, ecs::JobSystem& jobs, float deltaSeconds);

// Rebuilds every Skin's joint matrices (keeping the previous frame's) and deformed bounds.
// Call after transform propagation.
void updateSkins(ecs::Registry& registry, ecs::JobSystem& jobs);

// Declares both on a scheduler: "sample animation" in Update, "joint matrices" in
// PostUpdate (declare it after the transform system, which writes what it reads).
void addAnimationSystems(ecs::Scheduler& scheduler, std::function<float()> deltaSeconds);

// Per joint index below jointCount, the bind-space box of the vertices it moves (see
// Mesh::jointBounds).
std::vector<std::array<float, 6>> jointBoundsOf(const Mesh& mesh, std::size_t jointCount);

// Points Skin::jointBounds at the mesh's (instantiateModel calls it); a mesh the loader did not
// fill (a model built by hand) gets the skin its own copy.
void computeJointBounds(const Model& model, std::int32_t mesh, Skin& skin);

}  // namespace candela::content
