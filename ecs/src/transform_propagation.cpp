#include <candela/ecs/transform_propagation.h>

#include <algorithm>

#include <candela/ecs/affine_multiply.h>
#include <candela/ecs/hierarchy.h>
#include <candela/ecs/registry.h>
#include <candela/ecs/transform.h>

namespace candela::ecs {

void TransformPropagation::rebuildOrder(Registry& registry, ComponentPool& local,
                                        ComponentPool& world) {
    // Gather the entities with both transforms, with their parent.
    struct Entry {
        Entity entity;
        Entity parent;
        std::uint32_t localIndex;
        std::uint32_t worldIndex;
    };
    std::vector<Entry> entries;
    entries.reserve(local.size());
    const ComponentPool* nodes = registry.pool<HierarchyNode>();
    for (std::uint32_t i = 0; i < local.size(); ++i) {
        const Entity e = local.entities()[i];
        const std::uint32_t w = world.indexOf(e);
        if (w == ComponentPool::kAbsent) continue;
        const std::uint32_t n = nodes ? nodes->indexOf(e) : ComponentPool::kAbsent;
        const HierarchyNode* node =
            n == ComponentPool::kAbsent ? nullptr : nodes->typedData<HierarchyNode>() + n;
        entries.push_back({e, node ? node->parent : kNullEntity, i, w});
    }

    // Depth-first, one tree after another: parents land before children, and each tree
    // (a character's skeleton, a prop and its parts) lies contiguous in the pools, so code
    // that walks one tree at a time (the animation's skeleton pass) touches few cache lines.
    const std::size_t count = entries.size();
    constexpr std::uint32_t kNotListed = 0xFFFFFFFFu;
    std::vector<std::uint32_t> entryOf(registry.entityPool().slotCount(), kNotListed);
    for (std::uint32_t i = 0; i < count; ++i)
        entryOf[entries[i].entity.index()] = i;
    auto listedParent = [&](const Entry& entry) {
        return !entry.parent.isNull() && registry.valid(entry.parent) &&
               entryOf[entry.parent.index()] != kNotListed;
    };
    std::vector<std::uint32_t> order;
    order.reserve(count);
    std::vector<std::uint32_t> stack;
    for (std::uint32_t root = 0; root < count; ++root) {
        if (listedParent(entries[root])) continue;
        stack.push_back(root);
        while (!stack.empty()) {
            const std::uint32_t i = stack.back();
            stack.pop_back();
            order.push_back(i);
            // Children pushed last to first, so they come out in sibling order.
            const std::size_t mark = stack.size();
            const std::uint32_t n =
                nodes ? nodes->indexOf(entries[i].entity) : ComponentPool::kAbsent;
            Entity child = n == ComponentPool::kAbsent
                               ? kNullEntity
                               : nodes->typedData<HierarchyNode>()[n].firstChild;
            while (!child.isNull()) {
                const std::uint32_t c = entryOf[child.index()];
                if (c != kNotListed && entries[c].entity == child) stack.push_back(c);
                const std::uint32_t cn = nodes->indexOf(child);
                child = cn == ComponentPool::kAbsent
                            ? kNullEntity
                            : nodes->typedData<HierarchyNode>()[cn].nextSibling;
            }
            std::reverse(stack.begin() + static_cast<std::ptrdiff_t>(mark), stack.end());
        }
    }
    std::vector<std::uint32_t> slotOf(registry.entityPool().slotCount(), kNoParent);
    for (std::uint32_t slot = 0; slot < order.size(); ++slot)
        slotOf[entries[order[slot]].entity.index()] = slot;
    parent_.resize(count);
    for (std::size_t slot = 0; slot < count; ++slot) {
        const Entity parent = entries[order[slot]].parent;
        parent_[slot] =
            parent.isNull() || !registry.valid(parent) ? kNoParent : slotOf[parent.index()];
    }
    dirty_.assign(count, 1);
    localMatrix_.resize(count);

    // Sorting the pools reorders their dense arrays, which is a structural change: only when
    // nothing else is iterating, and not for pools a group keeps in its own order.
    poolsSorted_ =
        !registry.structureLocked() && local.group() == nullptr && world.group() == nullptr;
    if (poolsSorted_) {
        auto sortPool = [&](ComponentPool& pool, std::uint32_t Entry::*index) {
            std::vector<std::uint32_t> permutation;
            permutation.reserve(pool.size());
            std::vector<std::uint8_t> placed(pool.size(), 0);
            for (std::uint32_t entry : order) {
                permutation.push_back(entries[entry].*index);
                placed[entries[entry].*index] = 1;
            }
            // Elements without the other transform go after the ordered ones.
            for (std::uint32_t i = 0; i < pool.size(); ++i) {
                if (!placed[i]) permutation.push_back(i);
            }
            pool.permute(permutation);
        };
        sortPool(local, &Entry::localIndex);
        sortPool(world, &Entry::worldIndex);
        localIndex_.clear();
        worldIndex_.clear();
    } else {
        localIndex_.resize(count);
        worldIndex_.resize(count);
        for (std::size_t slot = 0; slot < count; ++slot) {
            localIndex_[slot] = entries[order[slot]].localIndex;
            worldIndex_[slot] = entries[order[slot]].worldIndex;
        }
    }
    localVersion_ = local.structureVersion();
    worldVersion_ = world.structureVersion();
    hierarchyVersion_ = hierarchyVersion(registry);
    built_ = true;
}

template <class LocalIndex, class WorldIndex>
std::uint32_t TransformPropagation::propagate(ComponentPool& local, ComponentPool& world,
                                              Tick since, Tick now, bool all, LocalIndex localIndex,
                                              WorldIndex worldIndex) {
    const LocalTransform* locals = local.typedData<LocalTransform>();
    const Tick* localTicks = local.changeTicks();
    WorldTransform* worlds = world.typedData<WorldTransform>();
    Tick* worldTicks = world.changeTicks();
    const std::uint32_t* parents = parent_.data();
    std::uint8_t* dirty = dirty_.data();
    Mat4* localMatrix = localMatrix_.data();
    const std::size_t count = parent_.size();
    std::uint32_t recomputed = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint32_t l = localIndex(i);
        const bool localChanged = all || localTicks[l] > since;
        if (localChanged) {
            const LocalTransform& t = locals[l];
            localMatrix[i] = Mat4::fromTranslationRotationScale(t.position, t.rotation, t.scale);
        }
        const std::uint32_t parent = parents[i];
        const bool isDirty = localChanged || (parent != kNoParent && dirty[parent] != 0);
        dirty[i] = isDirty ? 1 : 0;
        if (!isDirty) continue;
        const std::uint32_t w = worldIndex(i);
        if (parent == kNoParent) {
            worlds[w].matrix = localMatrix[i];
        } else {
            multiplyByAffine(worlds[worldIndex(parent)].matrix, localMatrix[i], worlds[w].matrix);
        }
        worldTicks[w] = now;
        ++recomputed;
    }
    return recomputed;
}

TransformPropagation::Stats TransformPropagation::updateChanged(Registry& registry,
                                                                ComponentPool* local,
                                                                ComponentPool* world) {
    Stats stats;
    // Close the current tick: local changes up to `upTo` are handled now, later ones next run.
    const Tick upTo = registry.advanceTick();
    const Tick since = lastSeen_;
    lastSeen_ = upTo;
    if (local == nullptr || world == nullptr) return stats;

    const bool rebuild = !orderIsCurrent(registry, *local, *world);
    if (rebuild) rebuildOrder(registry, *local, *world);
    stats.rebuiltOrder = rebuild;
    stats.entities = static_cast<std::uint32_t>(parent_.size());
    if (!rebuild && local->latestChange() <= since) {
        stats.skipped = true;
        return stats;
    }

    const Tick now = registry.currentTick();
    if (poolsSorted_) {
        auto identity = [](std::size_t i) { return static_cast<std::uint32_t>(i); };
        stats.recomputed = propagate(*local, *world, since, now, rebuild, identity, identity);
    } else {
        const std::uint32_t* l = localIndex_.data();
        const std::uint32_t* w = worldIndex_.data();
        stats.recomputed = propagate(
            *local, *world, since, now, rebuild, [l](std::size_t i) { return l[i]; },
            [w](std::size_t i) { return w[i]; });
    }
    if (stats.recomputed > 0) world->noteChange(now);
    return stats;
}

}  // namespace candela::ecs
