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

// Fills Skin::jointBounds from the mesh's vertices (instantiateModel calls it).
void computeJointBounds(const Model& model, std::int32_t mesh, Skin& skin);

}  // namespace candela::content
