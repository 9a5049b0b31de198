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

}  // namespace detail

Registry::Registry() : Registry(Config{}) {}

Registry::Registry(Config config) : pool_(config.maxGeneration) {}

Registry::~Registry() {
    // Resources may hold entity handles or refer to components; drop them first.
    resources_.clear();
}

Entity Registry::create() {
    checkStructureUnlocked();
    pool_.materialize();
    ++alive_;
    return pool_.allocate();
}

void Registry::createReserved(Entity e) {
    checkStructureUnlocked();
    pool_.materialize();
    CANDELA_ECS_CHECK(pool_.isReserved(e), EcsErrorCode::StaleEntity,
                      "createReserved() on a handle that is not reserved");
    pool_.activateReserved(e.index());
    ++alive_;
}

void Registry::releaseReserved(Entity e) {
    pool_.materialize();
    if (pool_.isReserved(e)) pool_.release(e.index());
}

bool Registry::destroy(Entity e) {
    if (!pool_.alive(e)) return false;
    checkStructureUnlocked();
    // Every on-remove hook first, while all of the entity's components are still readable.
    for (ComponentRecord& r : components_) {
        if (!r.onRemove.empty() && r.pool->contains(e)) fireHooks(r.onRemove, e);
    }
    for (ComponentRecord& r : components_) {
        ComponentPool* pool = r.pool.get();
        if (pool == nullptr || pool->size() == 0 || !pool->contains(e)) continue;
        if (detail::Group* group = pool->group()) leaveGroup(*group, e);
        pool->erase(e);
    }
    pool_.release(e.index());
    --alive_;
    return true;
}

Registry::ComponentRecord& Registry::record(ComponentId id) {
    if (id >= components_.size()) components_.resize(id + 1);
    return components_[id];
}

ComponentPool& Registry::createPool(ComponentId id, const ComponentOps& ops) {
    ComponentRecord& r = record(id);
    r.pool = std::make_unique<ComponentPool>(id, ops);
    if (id >= poolsById_.size()) poolsById_.resize(id + 1, nullptr);
    poolsById_[id] = r.pool.get();
    return *r.pool;
}

void Registry::enterGroup(detail::Group& group, Entity e) noexcept {
    ComponentPool& first = *group.pools.front();
    if (first.indexOf(e) < group.size) return;  // already a member
    for (const ComponentPool* pool : group.pools) {
        if (!pool->contains(e)) return;
    }
    for (ComponentPool* pool : group.pools)
        pool->swapPositions(pool->indexOf(e), group.size);
    ++group.size;
}

void Registry::leaveGroup(detail::Group& group, Entity e) noexcept {
    ComponentPool& first = *group.pools.front();
    const std::uint32_t index = first.indexOf(e);
    if (index == ComponentPool::kAbsent || index >= group.size) return;
    --group.size;
    for (ComponentPool* pool : group.pools)
        pool->swapPositions(pool->indexOf(e), group.size);
}

detail::Group& Registry::declareGroup(std::vector<ComponentPool*> pools) {
    std::sort(pools.begin(), pools.end(),
              [](const ComponentPool* a, const ComponentPool* b) { return a->id() < b->id(); });
    // Declaring the same group twice is fine; overlapping different groups is not.
    if (detail::Group* existing = pools.front()->group()) {
        if (existing->pools == pools) return *existing;
    }
    for (const ComponentPool* pool : pools) {
        CANDELA_ECS_CHECK(pool->group() == nullptr, EcsErrorCode::GroupConflict,
                          "a component pool can belong to one group only");
    }
    checkStructureUnlocked();
    auto group = std::make_unique<detail::Group>();
    group->pools = std::move(pools);
    for (ComponentPool* pool : group->pools)
        pool->setGroup(group.get());
    // Pack the entities that already have every component.
    const ComponentPool* smallest = *std::min_element(
        group->pools.begin(), group->pools.end(),
        [](const ComponentPool* a, const ComponentPool* b) { return a->size() < b->size(); });
    std::vector<Entity> members(smallest->entities(), smallest->entities() + smallest->size());
    for (Entity e : members)
        enterGroup(*group, e);
    groups_.push_back(std::move(group));
    return *groups_.back();
}

void Registry::fireHooks(const std::vector<HookEntry>& hooks, Entity e) {
    const StructureLock lock(*this);
    // Index loop over a copy of each hook: a hook may connect or disconnect hooks.
    for (std::size_t i = 0; i < hooks.size(); ++i) {
        const ComponentHook fn = hooks[i].fn;
        fn(*this, e);
    }
}

HookId Registry::addHook(ComponentId id, bool onAdd, ComponentHook hook) {
    const std::uint32_t serial = nextHookSerial_++;
    auto& list = onAdd ? record(id).onAdd : record(id).onRemove;
    list.push_back(HookEntry{serial, std::move(hook)});
    return HookId{id, serial};
}

void Registry::disconnect(HookId id) {
    if (id.serial == 0 || id.component >= components_.size()) return;
    for (auto* list : {&components_[id.component].onAdd, &components_[id.component].onRemove}) {
        std::erase_if(*list, [&](const HookEntry& h) { return h.serial == id.serial; });
    }
}

}  // namespace candela::ecs
