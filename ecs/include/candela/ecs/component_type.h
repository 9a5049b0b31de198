#pragma once
// Component types need no registration: any nothrow-movable type gets a process-wide id the
// first time it is used, and a table of the few type-erased operations the storage needs.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>

namespace candela::ecs {

using ComponentId = std::uint32_t;

namespace detail {
ComponentId allocateComponentId() noexcept;
}  // namespace detail

template <class T>
concept Component = std::is_same_v<T, std::remove_cvref_t<T>> && std::is_object_v<T> &&
    std::is_nothrow_move_constructible_v<T> && std::is_nothrow_destructible_v<T>;

// Always inlined: in a lookup loop it is then a guard-byte test the loop can keep in a
// register, not a call per component access.
template <Component T>
[[gnu::always_inline]] inline ComponentId componentId() noexcept {
    static const ComponentId id = detail::allocateComponentId();
    return id;
}

// What storage needs to move and destroy components without knowing T.
struct ComponentOps {
    std::size_t size;
    std::size_t alignment;
    bool trivial;  // trivially copyable: relocation is memcpy, destruction is a no-op
    void (*relocate)(void* dst, void* src) noexcept;  // move-construct dst, destroy src
    void (*destroy)(void* object) noexcept;
};

template <Component T>
const ComponentOps& componentOps() noexcept {
    static constexpr ComponentOps ops{
        sizeof(T),
        alignof(T),
        std::is_trivially_copyable_v<T>,
        [](void* dst, void* src) noexcept {
            T* from = static_cast<T*>(src);
            ::new (dst) T(std::move(*from));
            from->~T();
        },
        [](void* object) noexcept { static_cast<T*>(object)->~T(); },
    };
    return ops;
}

}  // namespace candela::ecs
