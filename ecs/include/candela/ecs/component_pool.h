#pragma once
// Storage for one component type: a sparse set. Three parallel dense arrays (entities,
// components, change ticks) hold every entity that has the component, packed with no holes;
// a paged sparse array maps an entity index to its dense position. Adding appends, removing
// moves the last element into the hole, so both are O(1) and iteration is a walk over plain
// arrays. Groups (see registry.h) keep several pools in the same order so a multi-component
// loop is as tight as a loop over separate std::vectors.
#include <array>
#include <atomic>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#include <candela/ecs/component_type.h>
#include <candela/ecs/entity.h>
#include <candela/ecs/tick.h>

namespace candela::ecs {

namespace detail {
struct Group;

// Copies a trivially copyable component of run-time size. Small sizes (the common case) are
// two overlapping fixed-size copies, which compile to plain moves instead of a memcpy call.
inline void copyComponent(std::byte* dst, const std::byte* src, std::size_t n) noexcept {
    struct Bytes16 {
        unsigned char b[16];
    };
    if (n >= 8 && n <= 16) {
        std::uint64_t head, tail;
        std::memcpy(&head, src, 8);
        std::memcpy(&tail, src + n - 8, 8);
        std::memcpy(dst, &head, 8);
        std::memcpy(dst + n - 8, &tail, 8);
    } else if (n >= 4 && n < 8) {
        std::uint32_t head, tail;
        std::memcpy(&head, src, 4);
        std::memcpy(&tail, src + n - 4, 4);
        std::memcpy(dst, &head, 4);
        std::memcpy(dst + n - 4, &tail, 4);
    } else if (n > 16 && n <= 32) {
        Bytes16 head, tail;
        std::memcpy(&head, src, 16);
        std::memcpy(&tail, src + n - 16, 16);
        std::memcpy(dst, &head, 16);
        std::memcpy(dst + n - 16, &tail, 16);
    } else {
        std::memcpy(dst, src, n);
    }
}
}  // namespace detail

class ComponentPool {
public:
    static constexpr std::uint32_t kAbsent = 0xFFFFFFFFu;

    ComponentPool(ComponentId id, const ComponentOps& ops);
    ~ComponentPool();
    ComponentPool(const ComponentPool&) = delete;
    ComponentPool& operator=(const ComponentPool&) = delete;

    ComponentId id() const noexcept { return id_; }
    std::uint32_t size() const noexcept { return size_; }
    const Entity* entities() const noexcept { return entities_; }
    std::byte* data() const noexcept { return data_; }
    Tick* changeTicks() const noexcept { return ticks_; }
    template <class T>
    T* typedData() const noexcept {
        return reinterpret_cast<T*>(data_);
    }

    // Dense position of e's component, or kAbsent. Callers check the entity is alive first.
    std::uint32_t indexOf(Entity e) const noexcept {
        const std::uint32_t page = e.index() >> kPageBits;
        if (page >= pages_.size()) return kAbsent;
        return pages_[page][e.index() & kPageMask];  // unallocated pages: absentPage()
    }
    bool contains(Entity e) const noexcept { return indexOf(e) != kAbsent; }
    // Dense position of an entity known to have the component (Storage<T>::get): no bounds
    // or presence checks, debug builds assert.
    std::uint32_t indexOfPresent(Entity e) const noexcept {
        assert(contains(e) && "component absent");
        return pages_[e.index() >> kPageBits][e.index() & kPageMask];
    }
    std::byte* at(std::uint32_t index) const noexcept { return data_ + index * elementSize_; }

    // Appends e; its component is left for the caller to construct at the returned index.
    std::uint32_t pushBack(Entity e) {
        if (size_ == capacity_) grow();
        std::uint32_t& entry = sparseEntry(e.index());
        entry = size_;
        entities_[size_] = e;
        ++structureVersion_;
        return size_++;
    }
    // Destroys e's component and closes the hole with the last element.
    void erase(Entity e) noexcept {
        const std::uint32_t index = indexOf(e);
        if (!trivial_) ops_->destroy(at(index));
        const std::uint32_t last = --size_;
        if (index != last) {
            relocate(index, last);
            const Entity moved = entities_[last];
            entities_[index] = moved;
            pages_[moved.index() >> kPageBits][moved.index() & kPageMask] = index;
        }
        pages_[e.index() >> kPageBits][e.index() & kPageMask] = kAbsent;
        ++structureVersion_;
    }
    // Exchanges two dense positions (groups use this to pack their members at the front).
    void swapPositions(std::uint32_t a, std::uint32_t b) noexcept;
    // Reorders the dense arrays so position i holds what was at order[i].
    void permute(const std::vector<std::uint32_t>& order);
    void reserve(std::uint32_t capacity);

    // Change tracking: per element tick, plus the newest tick in the pool so change queries
    // skip an unchanged pool without looking at its elements.
    void stamp(std::uint32_t index, Tick tick) noexcept {
        ticks_[index] = tick;
        noteChange(tick);
    }
    // Safe from parallel systems: ticks only grow, so keep the maximum.
    void noteChange(Tick tick) noexcept {
        Tick seen = latestChange_.load(std::memory_order_relaxed);
        while (seen < tick &&
               !latestChange_.compare_exchange_weak(seen, tick, std::memory_order_relaxed)) {
        }
    }
    Tick latestChange() const noexcept { return latestChange_.load(std::memory_order_relaxed); }

    // Bumped whenever elements are added, removed, reordered or reallocated: anything caching
    // positions or pointers into this pool compares it to know the cache is still good.
    std::uint32_t structureVersion() const noexcept { return structureVersion_; }

    // The group that keeps this pool ordered, if any (a pool belongs to at most one).
    detail::Group* group() const noexcept { return group_; }
    void setGroup(detail::Group* group) noexcept { group_ = group; }

private:
    static constexpr std::uint32_t kPageBits = 12;
    static constexpr std::uint32_t kPageSize = 1u << kPageBits;
    static constexpr std::uint32_t kPageMask = kPageSize - 1;

    std::uint32_t& sparseEntry(std::uint32_t entityIndex) {
        const std::uint32_t page = entityIndex >> kPageBits;
        if (page >= pages_.size() || pages_[page] == absentPage()) addPage(page);
        return pages_[page][entityIndex & kPageMask];
    }
    void addPage(std::uint32_t page);
    // A page of kAbsent entries standing in for every unallocated page, so a lookup needs no
    // null test. Shared by all pools and never written: writes go through sparseEntry, which
    // allocates first, or to the entries of entities the pool holds. Constant-initialised.
    static std::uint32_t* absentPage() noexcept { return absentEntries_.data(); }
    static constexpr std::array<std::uint32_t, kPageSize> makeAbsentPage() {
        std::array<std::uint32_t, kPageSize> page{};
        for (std::uint32_t& entry : page)
            entry = kAbsent;
        return page;
    }
    static inline std::array<std::uint32_t, kPageSize> absentEntries_ = makeAbsentPage();
    void grow();
    // Moves element `from` into the (vacated) position `to`.
    void relocate(std::uint32_t to, std::uint32_t from) noexcept {
        if (trivial_) {
            detail::copyComponent(at(to), at(from), elementSize_);
        } else {
            ops_->relocate(at(to), at(from));
        }
        ticks_[to] = ticks_[from];
    }

    ComponentId id_;
    const ComponentOps* ops_;
    std::size_t elementSize_;
    bool trivial_;
    std::uint32_t size_ = 0;
    std::uint32_t capacity_ = 0;
    std::uint32_t structureVersion_ = 0;
    std::byte* data_ = nullptr;
    Tick* ticks_ = nullptr;
    Entity* entities_ = nullptr;
    std::vector<std::uint32_t*> pages_;  // sparse: entity index -> dense position, by page
    std::vector<std::unique_ptr<std::uint32_t[]>> ownedPages_;
    std::atomic<Tick> latestChange_{kNeverTick};
    detail::Group* group_ = nullptr;
};

}  // namespace candela::ecs
