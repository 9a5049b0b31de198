#include <candela/ecs/resources.h>

#include <algorithm>
#include <atomic>

namespace candela::ecs {

namespace detail {
std::uint32_t allocateResourceId() noexcept {
    static std::atomic<std::uint32_t> next{0};
    return next.fetch_add(1, std::memory_order_relaxed);
}
}  // namespace detail

void Resources::clear() noexcept {
    while (true) {
        Slot* newest = nullptr;
        for (Slot& s : slots_) {
            if (s.object != nullptr && (newest == nullptr || s.order > newest->order)) newest = &s;
        }
        if (newest == nullptr) break;
        newest->reset();
    }
}

}  // namespace candela::ecs
