#pragma once
// Slot allocator for entity handles. Each slot records its current generation and whether it
// is alive. Destroying bumps the generation so old handles become stale; a slot whose
// generation would wrap is retired for good, so a stale handle can never alias a live
// entity. Handles can also be reserved from any thread (for command buffers); reserved slots
// are fresh indices past the end, so they never collide with the free list.
#include <atomic>
#include <cstdint>
#include <limits>
#include <vector>

#include <candela/ecs/entity.h>

namespace candela::ecs {

class EntityPool {
public:
    static constexpr std::uint32_t kMaxGeneration = std::numeric_limits<std::uint32_t>::max();

    enum class SlotState : std::uint32_t { Free, Alive, Reserved, Retired };
    struct Slot {
        std::uint32_t generation = 0;
        SlotState state = SlotState::Free;
    };

    // maxGeneration is lowered only by tests, to reach slot retirement quickly.
    explicit EntityPool(std::uint32_t maxGeneration = kMaxGeneration)
        : maxGeneration_(maxGeneration) {}

    // Takes a free slot (or a new one) and marks it alive.
    Entity allocate();
    // Frees a live or reserved slot: bumps its generation, or retires it if that would wrap.
    void release(std::uint32_t index);

    // Thread-safe: hands out a handle whose slot materialize() will create later.
    Entity reserve() noexcept;
    // Turns outstanding reservations into real (Reserved-state) slots. Not thread-safe.
    void materialize();
    // Reserved -> Alive.
    void activateReserved(std::uint32_t index) noexcept { slots_[index].state = SlotState::Alive; }

    bool alive(Entity e) const noexcept {
        const std::uint32_t i = e.index();
        return i < slots_.size() && slots_[i].generation == e.generation() &&
               slots_[i].state == SlotState::Alive;
    }
    bool isReserved(Entity e) const noexcept;

    const Slot& slot(std::uint32_t index) const noexcept { return slots_[index]; }
    std::size_t slotCount() const noexcept { return slots_.size(); }
    std::size_t freeCount() const noexcept { return freeList_.size(); }
    std::size_t retiredCount() const noexcept { return retired_; }
    void reserveCapacity(std::size_t n) {
        slots_.reserve(n);
        freeList_.reserve(n);
    }

    // Test hook: jump a free slot's generation ahead so retirement can be exercised.
    void setGenerationForTesting(std::uint32_t index, std::uint32_t generation) {
        slots_[index].generation = generation;
    }

private:
    std::vector<Slot> slots_;
    std::vector<std::uint32_t> freeList_;
    std::atomic<std::uint32_t> pendingReservations_{0};
    std::size_t retired_ = 0;
    std::uint32_t maxGeneration_;
};

}  // namespace candela::ecs
