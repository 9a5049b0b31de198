#pragma once
// A view visits every entity that has all the included components and none of the excluded
// ones. It walks the smallest included pool and looks the others up by entity; when the
// included types form an owning group (Registry::group), it walks the group's aligned arrays
// directly, which is as fast as a loop over plain arrays.
//
// Iteration holds the registry's structure lock: a structural change from inside the loop
// fails loudly (assert in debug, EcsError otherwise) instead of corrupting the arrays being
// walked. Record such changes in a CommandBuffer.
#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <optional>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include <candela/ecs/registry.h>

namespace candela::ecs {

// A slice of a view's walk: the unit handed to a parallel job.
struct ViewChunk {
    std::uint32_t begin;
    std::uint32_t end;
};

template <class... Ts, class... Excluded>
class View<TypeList<Ts...>, Exclude<Excluded...>> {
    static_assert(sizeof...(Ts) > 0, "a view needs at least one component");
    static constexpr std::size_t kCount = sizeof...(Ts);
    static constexpr std::size_t kExcluded = sizeof...(Excluded);
    template <class T>
    using Bare = std::remove_const_t<T>;
    using Indices = std::array<std::uint32_t, kCount>;

    // The pools behind the view, looked up at each walk (pools appear as types get used).
    struct Walk {
        std::array<ComponentPool*, kCount> pools{};
        std::array<const ComponentPool*, kExcluded> excluded{};
        std::size_t driver = 0;  // the pool whose dense array is walked
        bool aligned = false;    // an owning group: every pool has the same order in [0, end)
        std::uint32_t end = 0;   // dense positions to walk
    };

public:
    explicit View(Registry& registry) : registry_(&registry) {}

    // fn(Entity, Ts&...) or fn(Ts&...), for every matching entity.
    template <class F>
    void each(F&& fn) const {
        const Registry::StructureLock lock(*registry_);
        const Walk walk = plan();
        visit(walk, 0, walk.end, fn, std::index_sequence_for<Ts...>{});
    }

    // Splits the walk into slices of at most rowsPerChunk positions, for parallel jobs.
    std::vector<ViewChunk> chunks(std::uint32_t rowsPerChunk) const {
        const Walk walk = plan();
        std::vector<ViewChunk> out;
        if (rowsPerChunk == 0) rowsPerChunk = 1;
        for (std::uint32_t begin = 0; begin < walk.end; begin += rowsPerChunk) {
            const std::uint32_t end =
                walk.end - begin < rowsPerChunk ? walk.end : begin + rowsPerChunk;
            out.push_back(ViewChunk{begin, end});
        }
        return out;
    }

    // Visits one chunk from chunks(). Valid until the next structural change.
    template <class F>
    void each(const ViewChunk& chunk, F&& fn) const {
        const Registry::StructureLock lock(*registry_);
        const Walk walk = plan();
        visit(walk, chunk.begin, chunk.end < walk.end ? chunk.end : walk.end, fn,
              std::index_sequence_for<Ts...>{});
    }

    // Like each(), but only entities where any of Changed (default: all of Ts) was added or
    // changed after `since`. Returns at once if none of those pools changed after `since`.
    template <class... Changed, class F>
    void eachChangedSince(Tick since, F&& fn) const {
        const Registry::StructureLock lock(*registry_);
        const Walk walk = plan();
        using Watched = std::conditional_t<sizeof...(Changed) == 0, TypeList<Bare<Ts>...>,
                                           TypeList<Bare<Changed>...>>;
        const auto watched = watchedPools(Watched{});
        bool anyNewer = false;
        for (const ComponentPool* pool : watched) {
            anyNewer |= pool != nullptr && pool->latestChange() > since;
        }
        if (!anyNewer) return;
        auto filtered = [&](Entity e, Ts&... components) {
            for (const ComponentPool* pool : watched) {
                if (pool == nullptr) continue;
                const std::uint32_t index = pool->indexOf(e);
                if (index != ComponentPool::kAbsent && pool->changeTicks()[index] > since) {
                    call(fn, e, components...);
                    return;
                }
            }
        };
        visit(walk, 0, walk.end, filtered, std::index_sequence_for<Ts...>{});
    }

    // Number of matching entities.
    std::size_t size() const {
        const Walk walk = plan();
        if (walk.aligned || (kCount == 1 && kExcluded == 0)) return walk.end;
        std::size_t n = 0;
        Indices index{};
        for (std::uint32_t i = 0; i < walk.end; ++i)
            n += matches(walk, i, index) ? 1 : 0;
        return n;
    }
    bool empty() const { return size() == 0; }
    bool contains(Entity e) const {
        return registry_->template has<Bare<Ts>...>(e) &&
               !(registry_->template has<Bare<Excluded>>(e) || ...);
    }

    // Range-for support: `for (auto [entity, a, b] : view)`. The iterator holds the
    // structure lock for as long as it lives.
    class iterator {
    public:
        using value_type = std::tuple<Entity, Ts&...>;
        using difference_type = std::ptrdiff_t;

        iterator(const View& view) : lock_(std::in_place, *view.registry_), walk_(view.plan()) {
            settle();
        }
        value_type operator*() const { return deref(std::index_sequence_for<Ts...>{}); }
        iterator& operator++() {
            ++position_;
            settle();
            return *this;
        }
        bool operator==(std::default_sentinel_t) const { return position_ >= walk_.end; }

    private:
        void settle() {
            while (position_ < walk_.end && !matches(walk_, position_, index_))
                ++position_;
        }
        template <std::size_t... I>
        value_type deref(std::index_sequence<I...>) const {
            return value_type(walk_.pools[walk_.driver]->entities()[position_],
                              walk_.pools[I]->template typedData<Bare<Ts>>()[index_[I]]...);
        }
        std::optional<Registry::StructureLock> lock_;
        Walk walk_;
        std::uint32_t position_ = 0;
        Indices index_{};
    };

    iterator begin() const { return iterator(*this); }
    std::default_sentinel_t end() const { return {}; }

private:
    Walk plan() const {
        Walk walk;
        walk.pools = {registry_->findPool(componentId<Bare<Ts>>())...};
        for (const ComponentPool* pool : walk.pools) {
            if (pool == nullptr) return walk;  // a type nobody has: nothing to visit
        }
        if constexpr (kExcluded > 0) {
            walk.excluded = {registry_->findPool(componentId<Bare<Excluded>>())...};
        }
        const detail::Group* group = walk.pools[0]->group();
        bool aligned =
            kCount >= 2 && kExcluded == 0 && group != nullptr && group->pools.size() == kCount;
        for (const ComponentPool* pool : walk.pools)
            aligned = aligned && pool->group() == group;
        if (aligned) {
            walk.aligned = true;
            walk.end = group->size;
            return walk;
        }
        for (std::size_t k = 1; k < kCount; ++k) {
            if (walk.pools[k]->size() < walk.pools[walk.driver]->size()) walk.driver = k;
        }
        walk.end = walk.pools[walk.driver]->size();
        return walk;
    }

    // Does dense position i of the driver match? Fills each pool's position for it.
    static bool matches(const Walk& walk, std::uint32_t i, Indices& index) {
        if (walk.aligned) {
            index.fill(i);
            return true;
        }
        const Entity e = walk.pools[walk.driver]->entities()[i];
        for (std::size_t k = 0; k < kCount; ++k) {
            const ComponentPool& pool = *walk.pools[k];
            // Pools filled together share an order: try the same position before the lookup.
            index[k] = i < pool.size() && pool.entities()[i] == e ? i : pool.indexOf(e);
            if (index[k] == ComponentPool::kAbsent) return false;
        }
        for (const ComponentPool* pool : walk.excluded) {
            if (pool != nullptr && pool->contains(e)) return false;
        }
        return true;
    }

    template <class F, class... Components>
    static void call(F& fn, Entity e, Components&... components) {
        if constexpr (std::is_invocable_v<F&, Entity, Components&...>) {
            fn(e, components...);
        } else {
            static_assert(std::is_invocable_v<F&, Components&...>,
                          "view callback must take (Entity, Ts&...) or (Ts&...)");
            fn(components...);
        }
    }

    template <class F, std::size_t... I>
    static void visit(const Walk& walk, std::uint32_t begin, std::uint32_t end, F& fn,
                      std::index_sequence<I...>) {
        if (begin >= end) return;
        const std::tuple<Ts*...> data{walk.pools[I]->template typedData<Bare<Ts>>()...};
        const Entity* entities = walk.pools[walk.driver]->entities();
        if (walk.aligned || (kCount == 1 && kExcluded == 0)) {
            // Every pool is in the same order: a plain loop over arrays.
            for (std::uint32_t i = begin; i < end; ++i)
                call(fn, entities[i], std::get<I>(data)[i]...);
            return;
        }
        Indices index{};
        for (std::uint32_t i = begin; i < end; ++i) {
            if (matches(walk, i, index)) call(fn, entities[i], std::get<I>(data)[index[I]]...);
        }
    }

    template <class... Watched>
    std::array<const ComponentPool*, sizeof...(Watched)> watchedPools(TypeList<Watched...>) const {
        return {registry_->findPool(componentId<Watched>())...};
    }

    Registry* registry_;
};

}  // namespace candela::ecs
