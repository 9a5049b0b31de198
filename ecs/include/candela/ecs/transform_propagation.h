#pragma once
// Computes WorldTransform = parent's WorldTransform * LocalTransform for every entity that has
// both, parents before children.
//
// How it stays cheap:
//  - The propagation order (entities sorted by hierarchy depth, each with its parent's slot)
//    and pointers to their components are cached, and rebuilt only when the hierarchy or a
//    table holding transforms changed structure.
//  - If no LocalTransform changed since the last run (checked per table, not per entity),
//    the run returns at once.
//  - Otherwise one pass over the order recomputes only dirty entities: those whose
//    LocalTransform changed, and everything below them.
// Entities whose parent has no transforms are treated as roots.
#include <cstdint>
#include <vector>

#include <candela/ecs/tick.h>

namespace candela::ecs {

class Registry;
class Archetype;
struct LocalTransform;
struct WorldTransform;

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
    Stats update(Registry& registry);

private:
    bool orderIsCurrent(const Registry& registry) const;
    void rebuildOrder(Registry& registry);

    struct TableVersion {
        const Archetype* table;
        std::uint32_t version;
    };
    std::vector<TableVersion> tables_;
    std::uint64_t hierarchyVersion_ = 0;
    bool built_ = false;
    Tick lastSeen_ = kNeverTick;

    // The propagation order, as parallel arrays (parents always at lower slots).
    static constexpr std::uint32_t kNoParent = 0xFFFFFFFFu;
    std::vector<const LocalTransform*> local_;
    std::vector<const Tick*> localTick_;
    std::vector<WorldTransform*> world_;
    std::vector<Tick*> worldTick_;
    std::vector<std::uint32_t> parent_;
    std::vector<std::uint8_t> dirty_;
};

// Runs the registry's TransformPropagation (kept as a resource, created on first use).
TransformPropagation::Stats propagateTransforms(Registry& registry);

}  // namespace candela::ecs
