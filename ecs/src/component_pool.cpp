#include <candela/ecs/component_pool.h>

#include <algorithm>
#include <new>

namespace candela::ecs {
namespace {

constexpr std::size_t kMinAlignment = 64;  // cache line: array starts never share a line

void* allocateArray(std::size_t bytes, std::size_t alignment) {
    return ::operator new(bytes, std::align_val_t(std::max(alignment, kMinAlignment)));
}

void freeArray(void* p, std::size_t alignment) noexcept {
    ::operator delete(p, std::align_val_t(std::max(alignment, kMinAlignment)));
}

// A pool's three parallel arrays: components, change ticks, owning entities.
struct Arrays {
    std::byte* data;
    Tick* ticks;
    Entity* entities;
};

Arrays allocateArrays(std::uint32_t capacity, std::size_t elementSize, std::size_t alignment) {
    return {static_cast<std::byte*>(allocateArray(elementSize * capacity, alignment)),
            static_cast<Tick*>(allocateArray(sizeof(Tick) * capacity, alignof(Tick))),
            static_cast<Entity*>(allocateArray(sizeof(Entity) * capacity, alignof(Entity)))};
}

void freeArrays(const Arrays& arrays, std::size_t alignment) noexcept {
    freeArray(arrays.data, alignment);
    freeArray(arrays.ticks, alignof(Tick));
    freeArray(arrays.entities, alignof(Entity));
}

}  // namespace

ComponentPool::ComponentPool(ComponentId id, const ComponentOps& ops)
    : id_(id), ops_(&ops), elementSize_(ops.size), trivial_(ops.trivial) {}

ComponentPool::~ComponentPool() {
    if (!trivial_) {
        for (std::uint32_t i = 0; i < size_; ++i)
            ops_->destroy(at(i));
    }
    freeArrays({data_, ticks_, entities_}, ops_->alignment);
}

void ComponentPool::addPage(std::uint32_t page) {
    if (page >= pages_.size()) pages_.resize(page + 1, absentPage());
    auto entries = std::make_unique<std::uint32_t[]>(kPageSize);
    std::fill_n(entries.get(), kPageSize, kAbsent);
    pages_[page] = entries.get();
    ownedPages_.push_back(std::move(entries));
}

void ComponentPool::reserve(std::uint32_t capacity) {
    if (capacity <= capacity_) return;
    const auto [data, ticks, entities] = allocateArrays(capacity, elementSize_, ops_->alignment);
    if (size_ > 0) {
        if (trivial_) {
            std::memcpy(data, data_, elementSize_ * size_);
        } else {
            for (std::uint32_t i = 0; i < size_; ++i)
                ops_->relocate(data + i * elementSize_, at(i));
        }
        std::memcpy(ticks, ticks_, sizeof(Tick) * size_);
        std::memcpy(static_cast<void*>(entities), entities_, sizeof(Entity) * size_);
    }
    freeArrays({data_, ticks_, entities_}, ops_->alignment);
    data_ = data;
    ticks_ = ticks;
    entities_ = entities;
    capacity_ = capacity;
    ++structureVersion_;
}

void ComponentPool::grow() {
    reserve(capacity_ < 64 ? 64 : capacity_ * 2);
}

void ComponentPool::swapPositions(std::uint32_t a, std::uint32_t b) noexcept {
    if (a == b) return;
    // Swap through a temporary: on the stack unless the component is large or over-aligned.
    alignas(std::max_align_t) std::byte local[256];
    const bool fits = elementSize_ <= sizeof(local) && ops_->alignment <= alignof(std::max_align_t);
    std::byte* temp =
        fits ? local : static_cast<std::byte*>(allocateArray(elementSize_, ops_->alignment));
    if (trivial_) {
        detail::copyComponent(temp, at(a), elementSize_);
        detail::copyComponent(at(a), at(b), elementSize_);
        detail::copyComponent(at(b), temp, elementSize_);
    } else {
        ops_->relocate(temp, at(a));
        ops_->relocate(at(a), at(b));
        ops_->relocate(at(b), temp);
    }
    if (!fits) freeArray(temp, ops_->alignment);
    std::swap(ticks_[a], ticks_[b]);
    std::swap(entities_[a], entities_[b]);
    const Entity ea = entities_[a], eb = entities_[b];
    pages_[ea.index() >> kPageBits][ea.index() & kPageMask] = a;
    pages_[eb.index() >> kPageBits][eb.index() & kPageMask] = b;
    ++structureVersion_;
}

void ComponentPool::permute(const std::vector<std::uint32_t>& order) {
    const auto [data, ticks, entities] = allocateArrays(capacity_, elementSize_, ops_->alignment);
    for (std::uint32_t i = 0; i < size_; ++i) {
        const std::uint32_t from = order[i];
        if (trivial_) {
            detail::copyComponent(data + i * elementSize_, at(from), elementSize_);
        } else {
            ops_->relocate(data + i * elementSize_, at(from));
        }
        ticks[i] = ticks_[from];
        entities[i] = entities_[from];
        pages_[entities[i].index() >> kPageBits][entities[i].index() & kPageMask] = i;
    }
    freeArrays({data_, ticks_, entities_}, ops_->alignment);
    data_ = data;
    ticks_ = ticks;
    entities_ = entities;
    ++structureVersion_;
}

}  // namespace candela::ecs
