#pragma once
// An archetype is a table holding every entity that has exactly one set of component types.
// Each component type is a column: one contiguous array, so iterating a query walks plain
// arrays. Rows are kept dense: removing a row moves the last row into the hole.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <candela/ecs/component_type.h>
#include <candela/ecs/entity.h>
#include <candela/ecs/tick.h>

namespace candela::ecs {

class Archetype {
public:
    struct Column {
        ComponentId id = 0;
        const ComponentOps* ops = nullptr;
        std::byte* data = nullptr;
        Tick* changeTicks = nullptr;  // per row: when the component was last added or changed
        // The newest tick in changeTicks, so change queries skip unchanged tables whole.
        std::atomic<Tick> latestChange{kNeverTick};

        void* at(std::uint32_t row) const noexcept { return data + row * ops->size; }
        void stamp(std::uint32_t row, Tick tick) noexcept {
            changeTicks[row] = tick;
            noteChange(tick);
        }
        // Safe from parallel systems: ticks only grow, so keep the maximum.
        void noteChange(Tick tick) noexcept {
            Tick seen = latestChange.load(std::memory_order_relaxed);
            while (seen < tick &&
                   !latestChange.compare_exchange_weak(seen, tick, std::memory_order_relaxed)) {
            }
        }
    };

    Archetype(std::uint32_t index, std::vector<ComponentId> sortedIds,
              std::span<const ComponentOps* const> ops);
    ~Archetype();
    Archetype(const Archetype&) = delete;
    Archetype& operator=(const Archetype&) = delete;

    std::uint32_t index() const noexcept { return index_; }
    std::uint32_t size() const noexcept { return size_; }
    std::span<const ComponentId> componentIds() const noexcept { return ids_; }
    std::size_t columnCount() const noexcept { return ids_.size(); }
    const Entity* entities() const noexcept { return entities_; }

    // Column position of a component type, or -1 when this table lacks it.
    int columnIndex(ComponentId id) const noexcept {
        return id < columnOf_.size() ? columnOf_[id] : -1;
    }
    bool has(ComponentId id) const noexcept { return columnIndex(id) >= 0; }
    Column& column(std::size_t i) noexcept { return columns_[i]; }
    const Column& column(std::size_t i) const noexcept { return columns_[i]; }

    template <class T>
    T* typedColumn(std::size_t i) const noexcept {
        return reinterpret_cast<T*>(columns_[i].data);
    }

    // Bumped whenever rows are added, removed, moved or reallocated: anything caching row
    // pointers into this table compares it to know the cache is still good.
    std::uint32_t structureVersion() const noexcept { return structureVersion_; }

    // Appends a row for `e`; its component slots are left for the caller to construct.
    std::uint32_t pushRow(Entity e);
    // Destroys the components in `row`.
    void destroyRow(std::uint32_t row) noexcept;
    // Closes the hole at `row` (whose components were already moved out or destroyed) by moving
    // the last row into it. Returns the entity that moved, or null if `row` was the last.
    Entity fillHole(std::uint32_t row) noexcept;
    void reserve(std::uint32_t capacity);

    // Graph edges to the tables one component away, so add/remove skip the signature lookup.
    Archetype* addTarget(ComponentId id) const noexcept;
    Archetype* removeTarget(ComponentId id) const noexcept;
    void setAddTarget(ComponentId id, Archetype* target);
    void setRemoveTarget(ComponentId id, Archetype* target);

private:
    struct Edge {
        ComponentId id;
        Archetype* add;
        Archetype* remove;
    };
    Edge& edge(ComponentId id);
    void grow(std::uint32_t capacity);

    std::uint32_t index_;
    std::uint32_t size_ = 0;
    std::uint32_t capacity_ = 0;
    std::uint32_t structureVersion_ = 0;
    std::vector<ComponentId> ids_;
    std::vector<std::int16_t> columnOf_;  // component id -> column, -1 if absent
    std::unique_ptr<Column[]> columns_;
    Entity* entities_ = nullptr;
    std::vector<Edge> edges_;
};

}  // namespace candela::ecs
