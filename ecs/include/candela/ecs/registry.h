#pragma once
// The registry owns entities, their components (in archetype tables), component hooks,
// change ticks and resources. It is the one object systems and tools talk to.
//
// Threading: reads and component writes may run in parallel (the scheduler keeps writers of
// the same component apart). Structural changes (create, destroy, adding or removing
// components) are single-threaded and are rejected while any iteration or hook is running;
// record them in a CommandBuffer instead.
#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

#include <candela/ecs/archetype.h>
#include <candela/ecs/component_type.h>
#include <candela/ecs/entity.h>
#include <candela/ecs/entity_pool.h>
#include <candela/ecs/error.h>
#include <candela/ecs/query.h>
#include <candela/ecs/resources.h>
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
    // Pre-sizes the entity table and the component-less table for `count` more entities.
    void reserveEntities(std::size_t count);

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

    // ---- Queries -------------------------------------------------------------------------
    // registry.view<Position, const Velocity>(exclude<Frozen>): every entity with Position
    // and Velocity and without Frozen. Const components are read-only in the callback.
    template <class... Ts, class... Excluded>
    View<TypeList<Ts...>, Exclude<Excluded...>> view(Exclude<Excluded...> = {});

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

    // ---- Introspection -------------------------------------------------------------------
    std::size_t archetypeCount() const noexcept {
        return archetypeCount_.load(std::memory_order_acquire);
    }
    const Archetype& archetype(std::size_t i) const noexcept { return *archetypes_[i]; }
    const EntityPool& entityPool() const noexcept { return pool_; }
    EntityPool& entityPoolForTesting() noexcept { return pool_; }

    // Internal, for View: the refreshed table list of a query.
    template <class Include, class ExcludeList>
    detail::QueryCache& query() const;

private:
    template <class Include, class ExcludeList>
    friend class View;

    struct HookEntry {
        std::uint32_t serial;
        ComponentHook fn;
    };
    struct ComponentRecord {
        const ComponentOps* ops = nullptr;
        std::vector<HookEntry> onAdd;
        std::vector<HookEntry> onRemove;
    };
    struct SignatureHash {
        std::size_t operator()(const std::vector<ComponentId>& ids) const noexcept;
    };

    void checkStructureUnlocked() const {
        CANDELA_ECS_CHECK(!structureLocked(), EcsErrorCode::StructuralChangeWhileLocked,
                          "structural change while iterating or inside a hook; use a "
                          "CommandBuffer");
    }
    EntityPool::Slot& liveSlot(Entity e) {
        CANDELA_ECS_CHECK(pool_.alive(e), EcsErrorCode::StaleEntity, "stale entity handle");
        return pool_.slot(e.index());
    }
    const EntityPool::Slot& liveSlot(Entity e) const {
        CANDELA_ECS_CHECK(pool_.alive(e), EcsErrorCode::StaleEntity, "stale entity handle");
        return pool_.slot(e.index());
    }

    template <Component T>
    void registerType() {
        const ComponentId id = componentId<T>();
        if (id >= components_.size() || components_[id].ops == nullptr) {
            registerComponent(id, componentOps<T>());
        }
    }
    void registerComponent(ComponentId id, const ComponentOps& ops);
    Archetype& archetypeWith(Archetype& from, ComponentId added);
    Archetype& archetypeWithout(Archetype& from, ComponentId removed);
    Archetype& archetypeFor(std::vector<ComponentId> sortedIds);
    // Moves e's row to `target`, relocating shared components and destroying the rest.
    std::uint32_t moveEntity(EntityPool::Slot& slot, Archetype& target);
    void fireHooks(const std::vector<HookEntry>& hooks, Entity e);
    HookId addHook(ComponentId id, bool onAdd, ComponentHook hook);
    void refreshQuery(detail::QueryCache& cache) const;
    detail::QueryCache* findQuery(std::uint32_t queryId) const noexcept {
        const QueryChunk* chunk =
            queryChunks_[queryId / kQueriesPerChunk].load(std::memory_order_acquire);
        return chunk ? (*chunk)[queryId % kQueriesPerChunk].load(std::memory_order_acquire)
                     : nullptr;
    }
    detail::QueryCache& createQuery(std::uint32_t queryId, std::vector<ComponentId> include,
                                    std::vector<ComponentId> exclude) const;

    EntityPool pool_;
    std::size_t alive_ = 0;
    std::vector<std::unique_ptr<Archetype>> archetypes_;
    std::atomic<std::size_t> archetypeCount_{0};
    std::unordered_map<std::vector<ComponentId>, Archetype*, SignatureHash> archetypeIndex_;
    std::vector<ComponentRecord> components_;  // by ComponentId
    std::uint32_t nextHookSerial_ = 1;
    std::atomic<Tick> tick_{1};
    mutable std::atomic<int> structureLocks_{0};
    // Query caches by query id, in fixed chunks so lookups from parallel systems never see
    // a container being resized; creation and refresh take queryMutex_.
    static constexpr std::size_t kQueriesPerChunk = 256;
    static constexpr std::size_t kQueryChunks = 256;
    using QueryChunk = std::array<std::atomic<detail::QueryCache*>, kQueriesPerChunk>;
    mutable std::mutex queryMutex_;
    mutable std::array<std::atomic<QueryChunk*>, kQueryChunks> queryChunks_{};
    mutable std::vector<std::unique_ptr<QueryChunk>> ownedQueryChunks_;
    mutable std::vector<std::unique_ptr<detail::QueryCache>> ownedQueries_;
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

template <Component T, class... Args>
T& Registry::emplace(Entity e, Args&&... args) {
    EntityPool::Slot& slot = liveSlot(e);
    const ComponentId id = componentId<T>();
    const int existing = slot.table->columnIndex(id);
    if (existing >= 0) {
        T& ref = slot.table->typedColumn<T>(static_cast<std::size_t>(existing))[slot.row];
        T value = detail::makeComponent<T>(std::forward<Args>(args)...);
        ref.~T();
        ::new (static_cast<void*>(&ref)) T(std::move(value));
        slot.table->column(static_cast<std::size_t>(existing)).stamp(slot.row, currentTick());
        return ref;
    }
    checkStructureUnlocked();
    T value = detail::makeComponent<T>(std::forward<Args>(args)...);
    registerType<T>();
    Archetype& target = archetypeWith(*slot.table, id);
    const std::uint32_t row = moveEntity(slot, target);
    const auto column = static_cast<std::size_t>(target.columnIndex(id));
    T* component = ::new (target.column(column).at(row)) T(std::move(value));
    target.column(column).stamp(row, currentTick());
    if (!components_[id].onAdd.empty()) fireHooks(components_[id].onAdd, e);
    return *component;
}

template <Component T>
bool Registry::remove(Entity e) {
    if (!pool_.alive(e)) return false;
    EntityPool::Slot& slot = pool_.slot(e.index());
    const ComponentId id = componentId<T>();
    if (!slot.table->has(id)) return false;
    checkStructureUnlocked();
    if (!components_[id].onRemove.empty()) fireHooks(components_[id].onRemove, e);
    moveEntity(slot, archetypeWithout(*slot.table, id));
    return true;
}

template <Component T>
T* Registry::tryGet(Entity e) noexcept {
    if (!pool_.alive(e)) return nullptr;
    const EntityPool::Slot& slot = pool_.slot(e.index());
    const int column = slot.table->columnIndex(componentId<T>());
    if (column < 0) return nullptr;
    return slot.table->typedColumn<T>(static_cast<std::size_t>(column)) + slot.row;
}

template <Component T>
const T* Registry::tryGet(Entity e) const noexcept {
    return const_cast<Registry*>(this)->tryGet<T>(e);
}

template <Component T>
T& Registry::get(Entity e) {
    const EntityPool::Slot& slot = liveSlot(e);
    const int column = slot.table->columnIndex(componentId<T>());
    CANDELA_ECS_CHECK(column >= 0, EcsErrorCode::MissingComponent,
                      "get<T>() on an entity without T");
    return slot.table->typedColumn<T>(static_cast<std::size_t>(column))[slot.row];
}

template <Component T>
const T& Registry::get(Entity e) const {
    return const_cast<Registry*>(this)->get<T>(e);
}

template <Component... Ts>
bool Registry::has(Entity e) const noexcept {
    if (!pool_.alive(e)) return false;
    const Archetype& table = *pool_.slot(e.index()).table;
    return (table.has(componentId<Ts>()) && ...);
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
    const EntityPool::Slot& slot = liveSlot(e);
    const int column = slot.table->columnIndex(componentId<T>());
    CANDELA_ECS_CHECK(column >= 0, EcsErrorCode::MissingComponent,
                      "markChanged<T>() on an entity without T");
    slot.table->column(static_cast<std::size_t>(column)).stamp(slot.row, currentTick());
}

template <Component T>
Tick Registry::changeTick(Entity e) const noexcept {
    if (!pool_.alive(e)) return kNeverTick;
    const EntityPool::Slot& slot = pool_.slot(e.index());
    const int column = slot.table->columnIndex(componentId<T>());
    if (column < 0) return kNeverTick;
    return slot.table->column(static_cast<std::size_t>(column)).changeTicks[slot.row];
}

template <Component T>
HookId Registry::onAdd(ComponentHook hook) {
    registerType<T>();
    return addHook(componentId<T>(), true, std::move(hook));
}

template <Component T>
HookId Registry::onRemove(ComponentHook hook) {
    registerType<T>();
    return addHook(componentId<T>(), false, std::move(hook));
}

template <class Include, class ExcludeList>
detail::QueryCache& Registry::query() const {
    const std::uint32_t id = detail::queryId<Include, ExcludeList>();
    detail::QueryCache* cache = findQuery(id);
    if (cache == nullptr) {
        auto ids = []<class... Ts>(TypeList<Ts...>) {
            return std::vector<ComponentId>{componentId<Ts>()...};
        };
        cache = &createQuery(id, ids(Include{}), ids(typename ExcludeList::AsTypeList{}));
    }
    if (cache->tablesSeen.load(std::memory_order_acquire) != archetypeCount()) {
        refreshQuery(*cache);
    }
    return *cache;
}

template <class... Ts, class... Excluded>
View<TypeList<Ts...>, Exclude<Excluded...>> Registry::view(Exclude<Excluded...>) {
    return View<TypeList<Ts...>, Exclude<Excluded...>>(*this);
}

}  // namespace candela::ecs

#include <candela/ecs/view.h>
