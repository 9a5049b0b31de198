#pragma once
// Storage<T>: a typed handle on the pool of one component type, for hot loops that look
// components up by entity. registry.storage<T>() fetches the pool once; get(e) is then the
// sparse-set lookup alone: no liveness check, no membership check, no pool lookup.
//
//   const Storage<Position> positions = registry.storage<Position>();
//   for (Entity e : targets) sum += positions.get(e).y;  // every e alive and has Position
//
// Unchecked: the caller guarantees that e is alive and has T (debug builds assert both
// halves they can see: the slot is mapped and the dense entry is e). A stale handle or a
// missing component is undefined behaviour here; use Registry::get / tryGet when unsure.
// The handle stays valid for the registry's lifetime; references it returns, like any
// component reference, only until the next structural change to T's pool.
#include <cassert>

#include <candela/ecs/component_pool.h>
#include <candela/ecs/component_type.h>
#include <candela/ecs/entity.h>

namespace candela::ecs {

template <Component T>
class Storage {
public:
    explicit Storage(ComponentPool& pool) noexcept : pool_(&pool) {}

    T& get(Entity e) const noexcept {
        const std::uint32_t index = pool_->indexOfPresent(e);
        assert(pool_->entities()[index] == e && "Storage::get on a stale entity");
        return pool_->typedData<T>()[index];
    }
    bool contains(Entity e) const noexcept { return pool_->contains(e); }
    std::uint32_t size() const noexcept { return pool_->size(); }
    ComponentPool& pool() const noexcept { return *pool_; }

private:
    ComponentPool* pool_;
};

}  // namespace candela::ecs
