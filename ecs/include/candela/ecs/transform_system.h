#pragma once
// Registers transform propagation as a scheduler system (default: PostUpdate), with the
// accesses it needs declared, so systems that write LocalTransform run before it and
// systems that read WorldTransform run after it.
#include <candela/ecs/hierarchy.h>
#include <candela/ecs/scheduler.h>
#include <candela/ecs/transform.h>
#include <candela/ecs/transform_propagation.h>

namespace candela::ecs {

inline void addTransformSystem(Scheduler& scheduler, Phase phase = Phase::PostUpdate) {
    // Created here, not lazily inside a parallel stage where other systems read resources.
    scheduler.registry().resources().getOrEmplace<TransformPropagation>();
    scheduler
        .addSystem(
            "propagate transforms", phase,
            [](SystemContext& ctx) {
                ctx.registry().resources().get<TransformPropagation>().update(ctx.registry());
            })
        .reads<LocalTransform, HierarchyNode>()
        .writes<WorldTransform>()
        .writesResource<TransformPropagation>();
}

}  // namespace candela::ecs
