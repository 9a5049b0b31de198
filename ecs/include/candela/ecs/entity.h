#pragma once
// Entity handle: a 32-bit slot index plus a 32-bit generation, packed in 64 bits.
// The generation makes handles to destroyed entities detectably stale: destroying an entity
// bumps its slot's generation, so an old handle no longer matches the slot.
#include <cstdint>
#include <functional>

namespace candela::ecs {

class Entity {
public:
    static constexpr std::uint32_t kNullIndex = 0xFFFFFFFFu;

    constexpr Entity() = default;
    constexpr Entity(std::uint32_t index, std::uint32_t generation)
        : bits_(static_cast<std::uint64_t>(generation) << 32 | index) {}

    constexpr std::uint32_t index() const { return static_cast<std::uint32_t>(bits_); }
    constexpr std::uint32_t generation() const { return static_cast<std::uint32_t>(bits_ >> 32); }
    constexpr std::uint64_t bits() const { return bits_; }
    constexpr bool isNull() const { return index() == kNullIndex; }

    static constexpr Entity fromBits(std::uint64_t bits) {
        Entity e;
        e.bits_ = bits;
        return e;
    }

    friend constexpr bool operator==(Entity, Entity) = default;
    friend constexpr auto operator<=>(Entity, Entity) = default;

private:
    std::uint64_t bits_ = ~std::uint64_t{0};  // default-constructed handles are null
};

inline constexpr Entity kNullEntity{};

}  // namespace candela::ecs

template <>
struct std::hash<candela::ecs::Entity> {
    std::size_t operator()(candela::ecs::Entity e) const noexcept {
        return std::hash<std::uint64_t>{}(e.bits());
    }
};
