#include <candela/ecs/entity_pool.h>

#include <candela/ecs/error.h>

namespace candela::ecs {

Entity EntityPool::allocate() {
    if (!freeList_.empty()) {
        const std::uint32_t index = freeList_.back();
        freeList_.pop_back();
        slots_[index].state = SlotState::Alive;
        return Entity(index, slots_[index].generation);
    }
    CANDELA_ECS_CHECK(slots_.size() < Entity::kNullIndex, EcsErrorCode::EntityLimitReached,
                      "entity index space exhausted");
    const auto index = static_cast<std::uint32_t>(slots_.size());
    slots_.push_back(Slot{0, SlotState::Alive});
    return Entity(index, 0);
}

void EntityPool::release(std::uint32_t index) {
    Slot& s = slots_[index];
    if (s.generation >= maxGeneration_) {
        // Reusing this slot would wrap the generation and revive old handles: retire it.
        s.state = SlotState::Retired;
        ++retired_;
        return;
    }
    ++s.generation;
    s.state = SlotState::Free;
    freeList_.push_back(index);
}

Entity EntityPool::reserve() noexcept {
    const std::uint32_t offset = pendingReservations_.fetch_add(1, std::memory_order_relaxed);
    return Entity(static_cast<std::uint32_t>(slots_.size()) + offset, 0);
}

void EntityPool::materialize() {
    const std::uint32_t pending = pendingReservations_.exchange(0, std::memory_order_relaxed);
    if (pending == 0) return;
    CANDELA_ECS_CHECK(slots_.size() + pending < Entity::kNullIndex,
                      EcsErrorCode::EntityLimitReached, "entity index space exhausted");
    slots_.resize(slots_.size() + pending, Slot{0, SlotState::Reserved});
}

bool EntityPool::isReserved(Entity e) const noexcept {
    const std::uint32_t i = e.index();
    if (i >= slots_.size()) {
        return i < slots_.size() + pendingReservations_.load(std::memory_order_relaxed) &&
               e.generation() == 0;
    }
    return slots_[i].state == SlotState::Reserved && slots_[i].generation == e.generation();
}

}  // namespace candela::ecs
