#pragma once
// Computes WorldTransform = parent's WorldTransform * LocalTransform for every entity that has
// both, parents before children.
//
// How it stays cheap:
//  - The propagation order (entities sorted by hierarchy depth, each with its parent's slot)
//    is cached, and rebuilt only when the hierarchy or the transform pools changed structure.
//    When it may (not inside a parallel stage, pools not owned by a group), the rebuild also
//    sorts the LocalTransform and WorldTransform pools into that order, so a run is one
//    sequential pass over both arrays.
//  - If no LocalTransform changed since the last run (one tick compare for the whole pool),
//    the run returns at once without visiting the tree.
//  - Otherwise one pass recomputes only dirty entities: those whose LocalTransform changed,
//    and everything below them.
// Entities whose parent has no transforms are treated as roots.
#include <cstdint>
#include <vector>

#include <candela/ecs/hierarchy.h>
#include <candela/ecs/registry.h>
#include <candela/ecs/tick.h>
#include <candela/ecs/transform.h>
#include <candela/ecs/transform_math.h>

namespace candela::ecs {

class TransformPropagation {
public:
    struct Stats {
        std::uint32_t entities = 0;    // entities with both transforms
        std::uint32_t recomputed = 0;  // world matrices written this run
        bool rebuiltOrder = false;
        bool skipped = false;  // nothing changed: the tree was not visited
    };

    // Runs one propagation. Reads LocalTransform and HierarchyNode, writes WorldTransform
    // (stamped changed, so the renderer can upload only what moved).
    //
    // The "nothing changed" exit is always inlined: it is a handful of loads and compares,
    // and out of line most of its cost was handing Stats back (GCC packs it on the stack
    // with narrow stores and reloads it as words, a store-forwarding stall).
    [[gnu::always_inline]] Stats update(Registry& registry) {
        ComponentPool* local = registry.pool<LocalTransform>();
        ComponentPool* world = registry.pool<WorldTransform>();
        // Changes made after the last run carry ticks above lastSeen_, so returning without
        // advancing the tick (an atomic read-modify-write) loses none.
        if (built_ && local != nullptr && world != nullptr && local->latestChange() <= lastSeen_ &&
            orderIsCurrent(registry, *local, *world)) [[likely]] {
            return Stats{static_cast<std::uint32_t>(parent_.size()), 0, false, true};
        }
        return updateChanged(registry, local, world);
    }

private:
    Stats updateChanged(Registry& registry, ComponentPool* local, ComponentPool* world);
    bool orderIsCurrent(const Registry& registry, const ComponentPool& local,
                        const ComponentPool& world) const {
        return built_ && local.structureVersion() == localVersion_ &&
               world.structureVersion() == worldVersion_ &&
               hierarchyVersion(registry) == hierarchyVersion_;
    }
    void rebuildOrder(Registry& registry, ComponentPool& local, ComponentPool& world);
    template <class LocalIndex, class WorldIndex>
    std::uint32_t propagate(ComponentPool& local, ComponentPool& world, Tick since, Tick now,
                            bool all, LocalIndex localIndex, WorldIndex worldIndex);

    static constexpr std::uint32_t kNoParent = 0xFFFFFFFFu;

    bool built_ = false;
    std::uint32_t localVersion_ = 0;
    std::uint32_t worldVersion_ = 0;
    std::uint64_t hierarchyVersion_ = 0;
    Tick lastSeen_ = kNeverTick;

    // The propagation order: slot i's parent is at a lower slot (or kNoParent). When the pools
    // were sorted into this order, slot i is dense position i in both and the index arrays
    // stay empty.
    bool poolsSorted_ = false;
    std::vector<std::uint32_t> parent_;
    std::vector<std::uint32_t> localIndex_;
    std::vector<std::uint32_t> worldIndex_;
    std::vector<std::uint8_t> dirty_;
    // Each slot's LocalTransform as a matrix, refreshed only when it changes: a child under
    // a moving parent then costs one matrix product.
    std::vector<Mat4> localMatrix_;
};

// Runs the registry's TransformPropagation (kept as a resource, created on first use).
[[gnu::always_inline]] inline TransformPropagation::Stats propagateTransforms(Registry& registry) {
    return registry.resources().getOrEmplace<TransformPropagation>().update(registry);
}

}  // namespace candela::ecs
