#include <candela/ecs/registry.h>

#include <algorithm>

namespace candela::ecs {

namespace detail {

void throwEcsError(EcsErrorCode code, const char* what) {
    throw EcsError(code, what);
}

ComponentId allocateComponentId() noexcept {
    static std::atomic<ComponentId> next{0};
    return next.fetch_add(1, std::memory_order_relaxed);
}

std::uint32_t allocateQueryId() noexcept {
    static std::atomic<std::uint32_t> next{0};
    return next.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace detail

std::size_t Registry::SignatureHash::operator()(
    const std::vector<ComponentId>& ids) const noexcept {
    std::size_t h = 0xcbf29ce484222325ull;
    for (ComponentId id : ids)
        h = (h ^ id) * 0x100000001b3ull;
    return h;
}

Registry::Registry() : Registry(Config{}) {}

Registry::Registry(Config config) : pool_(config.maxGeneration) {
    archetypeFor({});
}

Registry::~Registry() {
    // Resources may hold entity handles or refer to tables; drop them first.
    resources_.clear();
}

void Registry::reserveEntities(std::size_t count) {
    pool_.reserveCapacity(pool_.slotCount() + count);
    Archetype& empty = *archetypes_[0];
    empty.reserve(static_cast<std::uint32_t>(empty.size() + count));
}

Entity Registry::create() {
    checkStructureUnlocked();
    pool_.materialize();
    const Entity e = pool_.allocate();
    EntityPool::Slot& slot = pool_.slot(e.index());
    Archetype& empty = *archetypes_[0];
    slot.table = &empty;
    slot.row = empty.pushRow(e);
    ++alive_;
    return e;
}

void Registry::createReserved(Entity e) {
    checkStructureUnlocked();
    pool_.materialize();
    CANDELA_ECS_CHECK(pool_.isReserved(e), EcsErrorCode::StaleEntity,
                      "createReserved() on a handle that is not reserved");
    EntityPool::Slot& slot = pool_.slot(e.index());
    slot.reserved = false;
    Archetype& empty = *archetypes_[0];
    slot.table = &empty;
    slot.row = empty.pushRow(e);
    ++alive_;
}

void Registry::releaseReserved(Entity e) {
    pool_.materialize();
    if (pool_.isReserved(e)) pool_.release(e.index());
}

bool Registry::destroy(Entity e) {
    if (!pool_.alive(e)) return false;
    checkStructureUnlocked();
    EntityPool::Slot& slot = pool_.slot(e.index());
    Archetype& table = *slot.table;
    for (ComponentId id : table.componentIds()) {
        if (!components_[id].onRemove.empty()) fireHooks(components_[id].onRemove, e);
    }
    table.destroyRow(slot.row);
    const Entity moved = table.fillHole(slot.row);
    if (!moved.isNull()) pool_.slot(moved.index()).row = slot.row;
    pool_.release(e.index());
    --alive_;
    return true;
}

void Registry::registerComponent(ComponentId id, const ComponentOps& ops) {
    if (id >= components_.size()) components_.resize(id + 1);
    components_[id].ops = &ops;
}

Archetype& Registry::archetypeFor(std::vector<ComponentId> sortedIds) {
    if (auto it = archetypeIndex_.find(sortedIds); it != archetypeIndex_.end()) {
        return *it->second;
    }
    std::vector<const ComponentOps*> ops;
    ops.reserve(sortedIds.size());
    for (ComponentId id : sortedIds)
        ops.push_back(components_[id].ops);
    const auto index = static_cast<std::uint32_t>(archetypes_.size());
    auto table = std::make_unique<Archetype>(index, sortedIds, ops);
    Archetype* raw = table.get();
    archetypes_.push_back(std::move(table));
    archetypeIndex_.emplace(std::move(sortedIds), raw);
    archetypeCount_.store(archetypes_.size(), std::memory_order_release);
    return *raw;
}

Archetype& Registry::archetypeWith(Archetype& from, ComponentId added) {
    if (Archetype* cached = from.addTarget(added)) return *cached;
    std::vector<ComponentId> ids(from.componentIds().begin(), from.componentIds().end());
    ids.insert(std::lower_bound(ids.begin(), ids.end(), added), added);
    Archetype& target = archetypeFor(std::move(ids));
    from.setAddTarget(added, &target);
    target.setRemoveTarget(added, &from);
    return target;
}

Archetype& Registry::archetypeWithout(Archetype& from, ComponentId removed) {
    if (Archetype* cached = from.removeTarget(removed)) return *cached;
    std::vector<ComponentId> ids(from.componentIds().begin(), from.componentIds().end());
    ids.erase(std::lower_bound(ids.begin(), ids.end(), removed));
    Archetype& target = archetypeFor(std::move(ids));
    from.setRemoveTarget(removed, &target);
    target.setAddTarget(removed, &from);
    return target;
}

std::uint32_t Registry::moveEntity(EntityPool::Slot& slot, Archetype& target) {
    Archetype& source = *slot.table;
    const std::uint32_t sourceRow = slot.row;
    const std::uint32_t targetRow = target.pushRow(source.entities()[sourceRow]);

    // Both column lists are sorted by id: walk them together.
    const std::size_t sourceColumns = source.columnCount();
    const std::size_t targetColumns = target.columnCount();
    std::size_t t = 0;
    for (std::size_t s = 0; s < sourceColumns; ++s) {
        Archetype::Column& from = source.column(s);
        while (t < targetColumns && target.column(t).id < from.id)
            ++t;
        void* src = from.at(sourceRow);
        if (t < targetColumns && target.column(t).id == from.id) {
            Archetype::Column& to = target.column(t);
            if (from.ops->trivial) {
                std::memcpy(to.at(targetRow), src, from.ops->size);
            } else {
                from.ops->relocate(to.at(targetRow), src);
            }
            to.changeTicks[targetRow] = from.changeTicks[sourceRow];
            to.noteChange(from.changeTicks[sourceRow]);
        } else if (!from.ops->trivial) {
            from.ops->destroy(src);
        }
    }
    const Entity moved = source.fillHole(sourceRow);
    if (!moved.isNull()) pool_.slot(moved.index()).row = sourceRow;
    slot.table = &target;
    slot.row = targetRow;
    return targetRow;
}

void Registry::fireHooks(const std::vector<HookEntry>& hooks, Entity e) {
    const StructureLock lock(*this);
    // Index loop: a hook may connect another hook (which may grow the vector).
    for (std::size_t i = 0; i < hooks.size(); ++i) {
        const ComponentHook fn = hooks[i].fn;
        fn(*this, e);
    }
}

HookId Registry::addHook(ComponentId id, bool onAdd, ComponentHook hook) {
    const std::uint32_t serial = nextHookSerial_++;
    auto& list = onAdd ? components_[id].onAdd : components_[id].onRemove;
    list.push_back(HookEntry{serial, std::move(hook)});
    return HookId{id, serial};
}

void Registry::disconnect(HookId id) {
    if (id.serial == 0 || id.component >= components_.size()) return;
    for (auto* list : {&components_[id.component].onAdd, &components_[id.component].onRemove}) {
        std::erase_if(*list, [&](const HookEntry& h) { return h.serial == id.serial; });
    }
}

detail::QueryCache& Registry::createQuery(std::uint32_t queryId, std::vector<ComponentId> include,
                                          std::vector<ComponentId> exclude) const {
    const std::lock_guard lock(queryMutex_);
    if (detail::QueryCache* existing = findQuery(queryId)) return *existing;
    std::atomic<QueryChunk*>& chunkSlot = queryChunks_[queryId / kQueriesPerChunk];
    QueryChunk* chunk = chunkSlot.load(std::memory_order_relaxed);
    if (chunk == nullptr) {
        ownedQueryChunks_.push_back(std::make_unique<QueryChunk>());
        chunk = ownedQueryChunks_.back().get();
        for (auto& p : *chunk)
            p.store(nullptr, std::memory_order_relaxed);
        chunkSlot.store(chunk, std::memory_order_release);
    }
    auto cache = std::make_unique<detail::QueryCache>();
    cache->include = std::move(include);
    cache->exclude = std::move(exclude);
    detail::QueryCache* raw = cache.get();
    ownedQueries_.push_back(std::move(cache));
    (*chunk)[queryId % kQueriesPerChunk].store(raw, std::memory_order_release);
    return *raw;
}

void Registry::refreshQuery(detail::QueryCache& cache) const {
    const std::lock_guard lock(queryMutex_);
    const std::size_t count = archetypeCount();
    for (std::size_t i = cache.tablesSeen.load(std::memory_order_relaxed); i < count; ++i) {
        Archetype& table = *archetypes_[i];
        const bool matches = std::all_of(cache.include.begin(), cache.include.end(),
                                         [&](ComponentId id) { return table.has(id); }) &&
                             std::none_of(cache.exclude.begin(), cache.exclude.end(),
                                          [&](ComponentId id) { return table.has(id); });
        if (!matches) continue;
        cache.tables.push_back(&table);
        for (ComponentId id : cache.include) {
            cache.columns.push_back(static_cast<std::uint32_t>(table.columnIndex(id)));
        }
    }
    cache.tablesSeen.store(count, std::memory_order_release);
}

}  // namespace candela::ecs
