#pragma once
// A view visits every entity that has all the included components and none of the excluded
// ones. It walks the matching archetype tables column by column, so the inner loop is a plain
// loop over arrays. Iteration holds the registry's structure lock: a structural change from
// inside the loop fails loudly instead of corrupting the arrays being walked.
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

// A slice of one table: the unit handed to a parallel job.
struct ViewChunk {
    std::uint32_t tableSlot;  // index into the view's matching tables
    std::uint32_t begin;
    std::uint32_t end;
};

template <class... Ts, class... Excluded>
class View<TypeList<Ts...>, Exclude<Excluded...>> {
    static_assert(sizeof...(Ts) > 0, "a view needs at least one component");
    static constexpr std::size_t kCount = sizeof...(Ts);
    using Query = TypeList<std::remove_const_t<Ts>...>;
    using ExcludeQuery = Exclude<std::remove_const_t<Excluded>...>;

public:
    explicit View(Registry& registry) : registry_(&registry) {}

    // fn(Entity, Ts&...) or fn(Ts&...), for every matching entity.
    template <class F>
    void each(F&& fn) const {
        const Registry::StructureLock lock(*registry_);
        const detail::QueryCache& cache = refreshed();
        for (std::size_t t = 0; t < cache.tables.size(); ++t) {
            const Archetype& table = *cache.tables[t];
            if (table.size() == 0) continue;
            visitRows(table, &cache.columns[t * kCount], 0, table.size(), fn,
                      std::index_sequence_for<Ts...>{});
        }
    }

    // Like each(), but only rows where any of Changed (default: all of Ts) was added or
    // changed after `since`. Whole tables with nothing newer are skipped.
    template <class... Changed, class F>
    void eachChangedSince(Tick since, F&& fn) const {
        const Registry::StructureLock lock(*registry_);
        const detail::QueryCache& cache = refreshed();
        for (std::size_t t = 0; t < cache.tables.size(); ++t) {
            const Archetype& table = *cache.tables[t];
            if (table.size() == 0) continue;
            const std::uint32_t* columns = &cache.columns[t * kCount];
            std::vector<const Tick*> ticks;
            bool anyNewer = false;
            auto addColumn = [&](std::size_t column) {
                const Archetype::Column& c = table.column(column);
                if (c.latestChange.load(std::memory_order_relaxed) <= since) return;
                anyNewer = true;
                ticks.push_back(c.changeTicks);
            };
            if constexpr (sizeof...(Changed) == 0) {
                for (std::size_t i = 0; i < kCount; ++i)
                    addColumn(columns[i]);
            } else {
                (addColumn(static_cast<std::size_t>(
                     table.columnIndex(componentId<std::remove_const_t<Changed>>()))),
                 ...);
            }
            if (!anyNewer) continue;
            std::uint32_t row = 0;
            while (row < table.size()) {
                // Find the next run of changed rows and visit it as one slice.
                auto changed = [&](std::uint32_t r) {
                    for (const Tick* tick : ticks) {
                        if (tick[r] > since) return true;
                    }
                    return false;
                };
                while (row < table.size() && !changed(row))
                    ++row;
                std::uint32_t end = row;
                while (end < table.size() && changed(end))
                    ++end;
                if (row < end) {
                    visitRows(table, columns, row, end, fn, std::index_sequence_for<Ts...>{});
                }
                row = end;
            }
        }
    }

    // Splits the matching rows into slices of at most rowsPerChunk, for parallel jobs.
    std::vector<ViewChunk> chunks(std::uint32_t rowsPerChunk) const {
        const detail::QueryCache& cache = refreshed();
        std::vector<ViewChunk> out;
        if (rowsPerChunk == 0) rowsPerChunk = 1;
        for (std::size_t t = 0; t < cache.tables.size(); ++t) {
            const std::uint32_t rows = cache.tables[t]->size();
            for (std::uint32_t begin = 0; begin < rows; begin += rowsPerChunk) {
                const std::uint32_t end = rows - begin < rowsPerChunk ? rows : begin + rowsPerChunk;
                out.push_back(ViewChunk{static_cast<std::uint32_t>(t), begin, end});
            }
        }
        return out;
    }

    // Visits one chunk from chunks(). Valid until the next structural change.
    template <class F>
    void each(const ViewChunk& chunk, F&& fn) const {
        const Registry::StructureLock lock(*registry_);
        const detail::QueryCache& cache = refreshed();
        const Archetype& table = *cache.tables[chunk.tableSlot];
        visitRows(table, &cache.columns[chunk.tableSlot * kCount], chunk.begin, chunk.end, fn,
                  std::index_sequence_for<Ts...>{});
    }

    // Number of matching entities.
    std::size_t size() const {
        std::size_t n = 0;
        for (const Archetype* table : refreshed().tables)
            n += table->size();
        return n;
    }
    bool empty() const { return size() == 0; }
    bool contains(Entity e) const {
        return registry_->template has<std::remove_const_t<Ts>...>(e) &&
               !(registry_->template has<std::remove_const_t<Excluded>>(e) || ...);
    }

    // Range-for support: `for (auto [entity, a, b] : view)`. The iterator holds the
    // structure lock for as long as it lives.
    class iterator {
    public:
        using value_type = std::tuple<Entity, Ts&...>;
        using difference_type = std::ptrdiff_t;

        iterator() = default;
        iterator(const Registry& registry, const detail::QueryCache* cache)
            : lock_(std::in_place, registry), cache_(cache) {
            skipEmptyTables();
        }
        value_type operator*() const {
            const Archetype& table = *cache_->tables[table_];
            const std::uint32_t* columns = &cache_->columns[table_ * kCount];
            return deref(table, columns, std::index_sequence_for<Ts...>{});
        }
        iterator& operator++() {
            if (++row_ == cache_->tables[table_]->size()) {
                ++table_;
                row_ = 0;
                skipEmptyTables();
            }
            return *this;
        }
        bool operator==(std::default_sentinel_t) const {
            return cache_ == nullptr || table_ == cache_->tables.size();
        }

    private:
        template <std::size_t... I>
        value_type deref(const Archetype& table, const std::uint32_t* columns,
                         std::index_sequence<I...>) const {
            return value_type(table.entities()[row_], table.typedColumn<Ts>(columns[I])[row_]...);
        }
        void skipEmptyTables() {
            while (table_ < cache_->tables.size() && cache_->tables[table_]->size() == 0) {
                ++table_;
            }
        }
        std::optional<Registry::StructureLock> lock_;
        const detail::QueryCache* cache_ = nullptr;
        std::size_t table_ = 0;
        std::uint32_t row_ = 0;
    };

    iterator begin() const { return iterator(*registry_, &refreshed()); }
    std::default_sentinel_t end() const { return {}; }

private:
    const detail::QueryCache& refreshed() const {
        return registry_->template query<Query, ExcludeQuery>();
    }

    template <class F, std::size_t... I>
    static void visitRows(const Archetype& table, const std::uint32_t* columns, std::uint32_t begin,
                          std::uint32_t end, F& fn, std::index_sequence<I...>) {
        const Entity* entities = table.entities();
        const std::tuple<Ts*...> data{table.typedColumn<Ts>(columns[I])...};
        for (std::uint32_t row = begin; row < end; ++row) {
            if constexpr (std::is_invocable_v<F&, Entity, Ts&...>) {
                fn(entities[row], std::get<I>(data)[row]...);
            } else {
                static_assert(std::is_invocable_v<F&, Ts&...>,
                              "view callback must take (Entity, Ts&...) or (Ts&...)");
                fn(std::get<I>(data)[row]...);
            }
        }
    }

    Registry* registry_;
};

}  // namespace candela::ecs
