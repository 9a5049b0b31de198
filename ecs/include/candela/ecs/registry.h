#pragma once
// The registry owns entities, their components (one sparse-set pool per component type, see
// component_pool.h), groups, component hooks, change ticks and resources. It is the one
// object systems and tools talk to.
//
// Threading: reads and component writes may run in parallel (the scheduler keeps writers of
// the same component apart). Structural changes (create, destroy, adding or removing
// components, declaring groups) are single-threaded and are rejected while any iteration or
// hook is running; record them in a CommandBuffer instead.
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include <candela/ecs/component_pool.h>
#include <candela/ecs/component_type.h>
#include <candela/ecs/entity.h>
#include <candela/ecs/entity_pool.h>
#include <candela/ecs/error.h>
#include <candela/ecs/query.h>
#include <candela/ecs/resources.h>
#include <candela/ecs/storage.h>
#include <candela/ecs/tick.h>

namespace candela::ecs {

template <class Include, class ExcludeList>
class View;

class Registry;
using ComponentHook = std::function<void(Registry&, Entity)>;

struct HookId {
    ComponentId component = 0;
    std::uint32_t serial = 0;  // 0 = no hook
};

namespace detail {
// An owning group keeps its pools' first `size` elements equal to the entities that have all
// of them, in the same order, so iterating the group is a walk over aligned plain arrays.
struct Group {
    std::vector<ComponentPool*> pools;
    std::uint32_t size = 0;
};
}  // namespace detail

class Registry {
public:
    struct Config {
        // Lowered only by tests, to reach slot retirement without 2^32 destroys.
        std::uint32_t maxGeneration = EntityPool::kMaxGeneration;
    };

    Registry();
    explicit Registry(Config config);
    ~Registry();
    Registry(const Registry&) = delete;
    Registry& operator=(const Registry&) = delete;

    // ---- Entities ------------------------------------------------------------------------
    Entity create();
    // Destroys the entity and its components (on-remove hooks fire first). Returns false for
    // a stale handle.
    bool destroy(Entity e);
    bool valid(Entity e) const noexcept { return pool_.alive(e); }
    std::size_t aliveCount() const noexcept { return alive_; }
    void reserveEntities(std::size_t count) { pool_.reserveCapacity(pool_.slotCount() + count); }
    // Calls fn(Entity) for every live entity (in slot order).
    template <class F>
    void forEachEntity(F&& fn) const;

    // Thread-safe: a handle that createReserved() will bring to life (command buffers use it).
    Entity reserve() noexcept { return pool_.reserve(); }
    bool isReserved(Entity e) const noexcept { return pool_.isReserved(e); }
    void createReserved(Entity e);
    void releaseReserved(Entity e);

    // ---- Components ----------------------------------------------------------------------
    // Adds T (constructed from args) or, if present, replaces its value. On-add hooks fire
    // only when T was not there before. Marks T changed either way.
    template <Component T, class... Args>
    T& emplace(Entity e, Args&&... args);
    // Removes T; on-remove hooks fire first. Returns false if the entity had no T or is stale.
    template <Component T>
    bool remove(Entity e);

    template <Component T>
    T& get(Entity e);
    template <Component T>
    const T& get(Entity e) const;
    template <Component T>
    T* tryGet(Entity e) noexcept;
    template <Component T>
    const T* tryGet(Entity e) const noexcept;
    // True if the entity is alive and has all of Ts.
    template <Component... Ts>
    bool has(Entity e) const noexcept;

    // Writes that also mark the component changed (what change queries and propagation see).
    // A plain get<T>() reference can be written too, but then call markChanged<T>().
    template <Component T>
    T& replace(Entity e, T value);
    template <Component T, class F>
    T& patch(Entity e, F&& edit);
    template <Component T>
    void markChanged(Entity e);
    // Tick of the last add/change of T on e (kNeverTick if absent).
    template <Component T>
    Tick changeTick(Entity e) const noexcept;
    template <Component T>
    bool changedSince(Entity e, Tick since) const noexcept {
        return changeTick<T>(e) > since;
    }

    // Typed handle on T's pool for hot lookup loops: Storage<T>::get(e) is unchecked (see
    // storage.h). EcsError MissingComponent if no T was ever added.
    template <Component T>
    Storage<T> storage() const;

    // ---- Queries -------------------------------------------------------------------------
    // registry.view<Position, const Velocity>(exclude<Frozen>): every entity with Position
    // and Velocity and without Frozen. Const components are read-only in the callback.
    template <class... Ts, class... Excluded>
    View<TypeList<Ts...>, Exclude<Excluded...>> view(Exclude<Excluded...> = {});
    // On a const registry every viewed component must be const: view<const Light>().
    template <class... Ts, class... Excluded>
    View<TypeList<Ts...>, Exclude<Excluded...>> view(Exclude<Excluded...> = {}) const;

    // Declares an owning group over Ts (once; later calls just return the view). From then
    // on the Ts pools keep the entities that have all of Ts packed at their front in the same
    // order, and any view of exactly Ts iterates them as plain arrays. Costs a few swaps per
    // add/remove of a Ts component. A pool can be owned by one group only (EcsError).
    template <Component... Ts>
    View<TypeList<Ts...>, Exclude<>> group();

    // ---- Hooks ---------------------------------------------------------------------------
    // Called once per add (after it) and once per removal (before it, so the value can still
    // be read), including removals by destroy(). Hooks may read and write components but not
    // change structure: record structural changes in a CommandBuffer.
    template <Component T>
    HookId onAdd(ComponentHook hook);
    template <Component T>
    HookId onRemove(ComponentHook hook);
    void disconnect(HookId id);

    // ---- Change ticks --------------------------------------------------------------------
    // Changes made now are stamped with currentTick(). A reader that wants every change once
    // calls `Tick upTo = advanceTick();`, visits what changed after its previous upTo, and
    // keeps upTo for next time; later changes get larger ticks.
    Tick currentTick() const noexcept { return tick_.load(std::memory_order_relaxed); }
    Tick advanceTick() noexcept { return tick_.fetch_add(1, std::memory_order_relaxed); }

    // ---- Resources -----------------------------------------------------------------------
    Resources& resources() noexcept { return resources_; }
    const Resources& resources() const noexcept { return resources_; }

    // ---- Structure lock ------------------------------------------------------------------
    // While any lock is held, structural changes fail (assert in debug, EcsError otherwise).
    // Views hold one while iterating; the scheduler holds one around parallel systems.
    class StructureLock {
    public:
        explicit StructureLock(const Registry& r) noexcept : registry_(&r) {
            registry_->structureLocks_.fetch_add(1, std::memory_order_relaxed);
        }
        StructureLock(StructureLock&& other) noexcept : registry_(other.registry_) {
            other.registry_ = nullptr;
        }
        StructureLock(const StructureLock&) = delete;
        StructureLock& operator=(const StructureLock&) = delete;
        StructureLock& operator=(StructureLock&&) = delete;
        ~StructureLock() {
            if (registry_) registry_->structureLocks_.fetch_sub(1, std::memory_order_relaxed);
        }

    private:
        const Registry* registry_;
    };
    StructureLock lockStructure() const noexcept { return StructureLock(*this); }
    bool structureLocked() const noexcept {
        return structureLocks_.load(std::memory_order_relaxed) != 0;
    }

    // ---- Storage access (views, propagation, tools) --------------------------------------
    // The pool of T, or null if no T was ever added.
    template <Component T>
    ComponentPool* pool() const noexcept {
        return findPool(componentId<T>());
    }
    ComponentPool* findPool(ComponentId id) const noexcept {
        return id < poolsById_.size() ? poolsById_[id] : nullptr;
    }
    const EntityPool& entityPool() const noexcept { return pool_; }
    EntityPool& entityPoolForTesting() noexcept { return pool_; }

private:
    struct HookEntry {
        std::uint32_t serial;
        ComponentHook fn;
    };
    struct ComponentRecord {
        std::unique_ptr<ComponentPool> pool;
        std::vector<HookEntry> onAdd;
        std::vector<HookEntry> onRemove;
    };

    void checkStructureUnlocked() const {
        CANDELA_ECS_CHECK(!structureLocked(), EcsErrorCode::StructuralChangeWhileLocked,
                          "structural change while iterating or inside a hook; use a "
                          "CommandBuffer");
    }
    void checkAlive(Entity e) const {
        CANDELA_ECS_CHECK(pool_.alive(e), EcsErrorCode::StaleEntity, "stale entity handle");
    }
    template <Component T>
    ComponentPool& poolOrCreate() {
        const ComponentId id = componentId<T>();
        if (ComponentPool* p = findPool(id)) return *p;
        return createPool(id, componentOps<T>());
    }
    ComponentPool& createPool(ComponentId id, const ComponentOps& ops);
    ComponentRecord& record(ComponentId id);
    // Group bookkeeping after e gained / before e loses a component of a grouped pool.
    void enterGroup(detail::Group& group, Entity e) noexcept;
    void leaveGroup(detail::Group& group, Entity e) noexcept;
    detail::Group& declareGroup(std::vector<ComponentPool*> pools);
    void fireHooks(const std::vector<HookEntry>& hooks, Entity e);
    HookId addHook(ComponentId id, bool onAdd, ComponentHook hook);

    EntityPool pool_;
    std::size_t alive_ = 0;
    std::vector<ComponentRecord> components_;  // by ComponentId
    // components_[id].pool.get(), packed: the component lookup of get/tryGet is one indexed
    // load instead of a stride-56 record walk.
    std::vector<ComponentPool*> poolsById_;
    std::vector<std::unique_ptr<detail::Group>> groups_;
    std::uint32_t nextHookSerial_ = 1;
    std::atomic<Tick> tick_{1};
    mutable std::atomic<int> structureLocks_{0};
    Resources resources_;
};

// ---- Template definitions ------------------------------------------------------------------

namespace detail {
template <class T, class... Args>
T makeComponent(Args&&... args) {
    // Parenthesised aggregate init is C++20 but clang 14 lacks it: braces for aggregates.
    if constexpr (std::is_constructible_v<T, Args...>) {
        return T(std::forward<Args>(args)...);
    } else {
        return T{std::forward<Args>(args)...};
    }
}
}  // namespace detail

template <class F>
void Registry::forEachEntity(F&& fn) const {
    const StructureLock lock(*this);
    for (std::size_t i = 0; i < pool_.slotCount(); ++i) {
        const EntityPool::Slot& slot = pool_.slot(static_cast<std::uint32_t>(i));
        if (slot.state == EntityPool::SlotState::Alive) {
            fn(Entity(static_cast<std::uint32_t>(i), slot.generation));
        }
    }
}

template <Component T, class... Args>
T& Registry::emplace(Entity e, Args&&... args) {
    checkAlive(e);
    const ComponentId id = componentId<T>();
    ComponentPool* pool = findPool(id);
    if (pool != nullptr) {
        if (const std::uint32_t index = pool->indexOf(e); index != ComponentPool::kAbsent) {
            T& ref = pool->typedData<T>()[index];
            T value = detail::makeComponent<T>(std::forward<Args>(args)...);
            ref.~T();
            ::new (static_cast<void*>(&ref)) T(std::move(value));
            pool->stamp(index, currentTick());
            return ref;
        }
    }
    checkStructureUnlocked();
    T value = detail::makeComponent<T>(std::forward<Args>(args)...);
    if (pool == nullptr) pool = &createPool(id, componentOps<T>());
    std::uint32_t index = pool->pushBack(e);
    ::new (static_cast<void*>(pool->at(index))) T(std::move(value));
    pool->stamp(index, currentTick());
    if (detail::Group* group = pool->group()) {
        enterGroup(*group, e);
        index = pool->indexOf(e);
    }
    if (!components_[id].onAdd.empty()) fireHooks(components_[id].onAdd, e);
    return pool->typedData<T>()[index];
}

template <Component T>
bool Registry::remove(Entity e) {
    if (!pool_.alive(e)) return false;
    const ComponentId id = componentId<T>();
    ComponentPool* pool = findPool(id);
    if (pool == nullptr || !pool->contains(e)) return false;
    checkStructureUnlocked();
    if (!components_[id].onRemove.empty()) fireHooks(components_[id].onRemove, e);
    if (detail::Group* group = pool->group()) leaveGroup(*group, e);
    pool->erase(e);
    return true;
}

// Always inlined (with get): in a lookup loop the call would cost as much as the lookup.
template <Component T>
[[gnu::always_inline]] inline T* Registry::tryGet(Entity e) noexcept {
    // Pools hold live entities only (destroy empties them first) and store full handles, so
    // "alive and has T" is "T's pool maps e's index to a slot holding exactly e": a stale
    // handle whose slot was reused carries another generation. One sparse-set lookup, no
    // trip to the entity slots.
    const ComponentPool* pool = findPool(componentId<T>());
    if (pool == nullptr) return nullptr;
    const std::uint32_t index = pool->indexOf(e);
    if (index == ComponentPool::kAbsent || pool->entities()[index] != e) return nullptr;
    return pool->typedData<T>() + index;
}

template <Component T>
const T* Registry::tryGet(Entity e) const noexcept {
    return const_cast<Registry*>(this)->tryGet<T>(e);
}

template <Component T>
[[gnu::always_inline]] inline T& Registry::get(Entity e) {
    T* component = tryGet<T>(e);
    if (component == nullptr) [[unlikely]] {
        checkAlive(e);
        CANDELA_ECS_CHECK(false, EcsErrorCode::MissingComponent, "get<T>() on an entity without T");
    }
    return *component;
}

template <Component T>
const T& Registry::get(Entity e) const {
    return const_cast<Registry*>(this)->get<T>(e);
}

template <Component T>
Storage<T> Registry::storage() const {
    ComponentPool* pool = findPool(componentId<T>());
    CANDELA_ECS_CHECK(pool != nullptr, EcsErrorCode::MissingComponent,
                      "storage<T>() before any T was added");
    return Storage<T>(*pool);
}

template <Component... Ts>
bool Registry::has(Entity e) const noexcept {
    if (!pool_.alive(e)) return false;
    auto contains = [&](const ComponentPool* pool) { return pool != nullptr && pool->contains(e); };
    return (contains(findPool(componentId<Ts>())) && ...);
}

template <Component T>
T& Registry::replace(Entity e, T value) {
    T& ref = get<T>(e);
    ref = std::move(value);
    markChanged<T>(e);
    return ref;
}

template <Component T, class F>
T& Registry::patch(Entity e, F&& edit) {
    T& ref = get<T>(e);
    std::forward<F>(edit)(ref);
    markChanged<T>(e);
    return ref;
}

template <Component T>
void Registry::markChanged(Entity e) {
    checkAlive(e);
    ComponentPool* pool = findPool(componentId<T>());
    const std::uint32_t index = pool ? pool->indexOf(e) : ComponentPool::kAbsent;
    CANDELA_ECS_CHECK(index != ComponentPool::kAbsent, EcsErrorCode::MissingComponent,
                      "markChanged<T>() on an entity without T");
    pool->stamp(index, currentTick());
}

template <Component T>
Tick Registry::changeTick(Entity e) const noexcept {
    if (!pool_.alive(e)) return kNeverTick;
    const ComponentPool* pool = findPool(componentId<T>());
    const std::uint32_t index = pool ? pool->indexOf(e) : ComponentPool::kAbsent;
    return index == ComponentPool::kAbsent ? kNeverTick : pool->changeTicks()[index];
}

template <Component T>
HookId Registry::onAdd(ComponentHook hook) {
    poolOrCreate<T>();
    return addHook(componentId<T>(), true, std::move(hook));
}

template <Component T>
HookId Registry::onRemove(ComponentHook hook) {
    poolOrCreate<T>();
    return addHook(componentId<T>(), false, std::move(hook));
}

template <class... Ts, class... Excluded>
View<TypeList<Ts...>, Exclude<Excluded...>> Registry::view(Exclude<Excluded...>) {
    return View<TypeList<Ts...>, Exclude<Excluded...>>(*this);
}

template <class... Ts, class... Excluded>
View<TypeList<Ts...>, Exclude<Excluded...>> Registry::view(Exclude<Excluded...>) const {
    static_assert((std::is_const_v<Ts> && ...), "a const registry gives read-only views only");
    // The view only reads through const component types; the lock counter is mutable.
    return View<TypeList<Ts...>, Exclude<Excluded...>>(const_cast<Registry&>(*this));
}

template <Component... Ts>
View<TypeList<Ts...>, Exclude<>> Registry::group() {
    static_assert(sizeof...(Ts) >= 2, "a group packs two or more component types");
    std::vector<ComponentPool*> pools{&poolOrCreate<Ts>()...};
    declareGroup(std::move(pools));
    return View<TypeList<Ts...>, Exclude<>>(*this);
}

}  // namespace candela::ecs

#include <candela/ecs/view.h>
