#include <candela/ecs/archetype.h>

#include <algorithm>
#include <cstring>
#include <new>

namespace candela::ecs {
namespace {

constexpr std::size_t kMinAlignment = 64;  // cache line: column starts never share a line

void* allocateArray(std::size_t bytes, std::size_t alignment) {
    return ::operator new(bytes, std::align_val_t(std::max(alignment, kMinAlignment)));
}

void freeArray(void* p, std::size_t alignment) noexcept {
    ::operator delete(p, std::align_val_t(std::max(alignment, kMinAlignment)));
}

void relocateRange(const ComponentOps& ops, std::byte* dst, std::byte* src,
                   std::uint32_t count) noexcept {
    if (ops.trivial) {
        if (count > 0) std::memcpy(dst, src, ops.size * count);
        return;
    }
    for (std::uint32_t i = 0; i < count; ++i)
        ops.relocate(dst + i * ops.size, src + i * ops.size);
}

}  // namespace

Archetype::Archetype(std::uint32_t index, std::vector<ComponentId> sortedIds,
                     std::span<const ComponentOps* const> ops)
    : index_(index), ids_(std::move(sortedIds)), columns_(new Column[ids_.size()]) {
    if (!ids_.empty()) columnOf_.assign(ids_.back() + 1, -1);
    for (std::size_t i = 0; i < ids_.size(); ++i) {
        columnOf_[ids_[i]] = static_cast<std::int16_t>(i);
        columns_[i].id = ids_[i];
        columns_[i].ops = ops[i];
    }
}

Archetype::~Archetype() {
    for (std::uint32_t row = 0; row < size_; ++row)
        destroyRow(row);
    for (std::size_t i = 0; i < ids_.size(); ++i) {
        freeArray(columns_[i].data, columns_[i].ops->alignment);
        freeArray(columns_[i].changeTicks, alignof(Tick));
    }
    freeArray(entities_, alignof(Entity));
}

void Archetype::grow(std::uint32_t capacity) {
    for (std::size_t i = 0; i < ids_.size(); ++i) {
        Column& c = columns_[i];
        auto* data =
            static_cast<std::byte*>(allocateArray(c.ops->size * capacity, c.ops->alignment));
        auto* ticks = static_cast<Tick*>(allocateArray(sizeof(Tick) * capacity, alignof(Tick)));
        if (c.data != nullptr) {
            relocateRange(*c.ops, data, c.data, size_);
            std::memcpy(ticks, c.changeTicks, sizeof(Tick) * size_);
            freeArray(c.data, c.ops->alignment);
            freeArray(c.changeTicks, alignof(Tick));
        }
        c.data = data;
        c.changeTicks = ticks;
    }
    auto* entities =
        static_cast<Entity*>(allocateArray(sizeof(Entity) * capacity, alignof(Entity)));
    if (entities_ != nullptr) {
        std::memcpy(static_cast<void*>(entities), entities_, sizeof(Entity) * size_);
        freeArray(entities_, alignof(Entity));
    }
    entities_ = entities;
    capacity_ = capacity;
    ++structureVersion_;
}

void Archetype::reserve(std::uint32_t capacity) {
    if (capacity > capacity_) grow(capacity);
}

std::uint32_t Archetype::pushRow(Entity e) {
    if (size_ == capacity_) grow(capacity_ < 64 ? 64 : capacity_ * 2);
    ::new (static_cast<void*>(entities_ + size_)) Entity(e);
    ++structureVersion_;
    return size_++;
}

void Archetype::destroyRow(std::uint32_t row) noexcept {
    for (std::size_t i = 0; i < ids_.size(); ++i) {
        const Column& c = columns_[i];
        if (!c.ops->trivial) c.ops->destroy(c.at(row));
    }
}

Entity Archetype::fillHole(std::uint32_t row) noexcept {
    const std::uint32_t last = --size_;
    ++structureVersion_;
    if (row == last) return kNullEntity;
    for (std::size_t i = 0; i < ids_.size(); ++i) {
        Column& c = columns_[i];
        if (c.ops->trivial) {
            std::memcpy(c.at(row), c.at(last), c.ops->size);
        } else {
            c.ops->relocate(c.at(row), c.at(last));
        }
        c.changeTicks[row] = c.changeTicks[last];
    }
    entities_[row] = entities_[last];
    return entities_[row];
}

Archetype::Edge& Archetype::edge(ComponentId id) {
    for (Edge& e : edges_) {
        if (e.id == id) return e;
    }
    return edges_.emplace_back(Edge{id, nullptr, nullptr});
}

Archetype* Archetype::addTarget(ComponentId id) const noexcept {
    for (const Edge& e : edges_) {
        if (e.id == id) return e.add;
    }
    return nullptr;
}

Archetype* Archetype::removeTarget(ComponentId id) const noexcept {
    for (const Edge& e : edges_) {
        if (e.id == id) return e.remove;
    }
    return nullptr;
}

void Archetype::setAddTarget(ComponentId id, Archetype* target) {
    edge(id).add = target;
}
void Archetype::setRemoveTarget(ComponentId id, Archetype* target) {
    edge(id).remove = target;
}

}  // namespace candela::ecs
