#include <candela/ecs/transform_propagation.h>

#include <algorithm>

#include <candela/ecs/hierarchy.h>
#include <candela/ecs/registry.h>
#include <candela/ecs/transform.h>

namespace candela::ecs {
namespace {

using TransformQuery = TypeList<LocalTransform, WorldTransform>;
using NoExclusions = Exclude<>;

const detail::QueryCache& transformTables(const Registry& registry) {
    return registry.query<TransformQuery, NoExclusions>();
}

}  // namespace

bool TransformPropagation::orderIsCurrent(const Registry& registry) const {
    if (!built_ || hierarchyVersion_ != hierarchyVersion(registry)) return false;
    const detail::QueryCache& cache = transformTables(registry);
    if (cache.tables.size() != tables_.size()) return false;
    for (std::size_t i = 0; i < tables_.size(); ++i) {
        if (cache.tables[i] != tables_[i].table ||
            cache.tables[i]->structureVersion() != tables_[i].version) {
            return false;
        }
    }
    return true;
}

void TransformPropagation::rebuildOrder(Registry& registry) {
    const detail::QueryCache& cache = transformTables(registry);
    tables_.clear();
    std::size_t count = 0;
    for (const Archetype* table : cache.tables) {
        tables_.push_back({table, table->structureVersion()});
        count += table->size();
    }

    // Gather (entity, depth, parent) and counting-sort by depth: parents land before children.
    struct Entry {
        Entity entity;
        Entity parent;
        std::uint32_t depth;
        std::uint32_t table;
        std::uint32_t row;
    };
    std::vector<Entry> entries;
    entries.reserve(count);
    std::uint32_t maxDepth = 0;
    for (std::size_t t = 0; t < cache.tables.size(); ++t) {
        const Archetype& table = *cache.tables[t];
        for (std::uint32_t row = 0; row < table.size(); ++row) {
            const Entity e = table.entities()[row];
            const HierarchyNode* node = registry.tryGet<HierarchyNode>(e);
            const std::uint32_t depth = node ? node->depth : 0;
            maxDepth = std::max(maxDepth, depth);
            entries.push_back(
                {e, node ? node->parent : kNullEntity, depth, static_cast<std::uint32_t>(t), row});
        }
    }
    std::vector<std::uint32_t> depthStart(std::size_t{maxDepth} + 2, 0);
    for (const Entry& entry : entries)
        ++depthStart[entry.depth + 1];
    for (std::size_t d = 1; d < depthStart.size(); ++d)
        depthStart[d] += depthStart[d - 1];

    std::vector<std::uint32_t> slotOf(registry.entityPool().slotCount(), kNoParent);
    std::vector<std::uint32_t> order(entries.size());
    for (std::uint32_t i = 0; i < entries.size(); ++i) {
        const std::uint32_t slot = depthStart[entries[i].depth]++;
        order[slot] = i;
        slotOf[entries[i].entity.index()] = slot;
    }

    local_.resize(count);
    localTick_.resize(count);
    world_.resize(count);
    worldTick_.resize(count);
    parent_.resize(count);
    dirty_.assign(count, 1);
    for (std::uint32_t slot = 0; slot < count; ++slot) {
        const Entry& entry = entries[order[slot]];
        Archetype& table = *cache.tables[entry.table];
        const std::uint32_t* columns = &cache.columns[entry.table * 2];
        local_[slot] = table.typedColumn<LocalTransform>(columns[0]) + entry.row;
        localTick_[slot] = table.column(columns[0]).changeTicks + entry.row;
        world_[slot] = table.typedColumn<WorldTransform>(columns[1]) + entry.row;
        worldTick_[slot] = table.column(columns[1]).changeTicks + entry.row;
        parent_[slot] = entry.parent.isNull() || !registry.valid(entry.parent)
                            ? kNoParent
                            : slotOf[entry.parent.index()];
    }
    hierarchyVersion_ = hierarchyVersion(registry);
    built_ = true;
}

TransformPropagation::Stats TransformPropagation::update(Registry& registry) {
    Stats stats;
    // Close the current tick: local changes up to `upTo` are handled now, later ones next run.
    const Tick upTo = registry.advanceTick();
    const Tick since = lastSeen_;
    lastSeen_ = upTo;

    const bool rebuild = !orderIsCurrent(registry);
    if (rebuild) rebuildOrder(registry);
    stats.rebuiltOrder = rebuild;
    stats.entities = static_cast<std::uint32_t>(local_.size());

    const detail::QueryCache& cache = transformTables(registry);
    if (!rebuild) {
        bool anyChanged = false;
        for (std::size_t t = 0; t < cache.tables.size(); ++t) {
            const Archetype::Column& local = cache.tables[t]->column(cache.columns[t * 2]);
            anyChanged |= local.latestChange.load(std::memory_order_relaxed) > since;
        }
        if (!anyChanged) {
            stats.skipped = true;
            return stats;
        }
    }

    const Tick now = registry.currentTick();
    const std::size_t count = local_.size();
    std::uint32_t recomputed = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint32_t parent = parent_[i];
        const bool dirty =
            rebuild || *localTick_[i] > since || (parent != kNoParent && dirty_[parent]);
        dirty_[i] = dirty;
        if (!dirty) continue;
        const LocalTransform& local = *local_[i];
        world_[i]->matrix = parent == kNoParent
                                ? local.matrix()
                                : composeWithLocal(world_[parent]->matrix, local.position,
                                                   local.rotation, local.scale);
        *worldTick_[i] = now;
        ++recomputed;
    }
    if (recomputed > 0) {
        for (std::size_t t = 0; t < cache.tables.size(); ++t) {
            cache.tables[t]->column(cache.columns[t * 2 + 1]).noteChange(now);
        }
    }
    stats.recomputed = recomputed;
    return stats;
}

TransformPropagation::Stats propagateTransforms(Registry& registry) {
    return registry.resources().getOrEmplace<TransformPropagation>().update(registry);
}

}  // namespace candela::ecs
