#pragma once
// The frame's guard against a forgotten markChanged<T>(): a component written through a plain
// get<T>() (or a view's mutable reference) whose value differs from what this check saw last
// frame while its change tick did not move. Each such component is marked changed now, so the
// frame shows the new value, and the entity is named once on stderr so the code can be fixed
// (registry.patch<T>(e, edit) writes and marks in one call).
#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>

#include "candela/ecs/registry.h"

namespace candela::runtime {

template <class T>
class UnmarkedChangeCheck {
public:
    explicit UnmarkedChangeCheck(std::string componentName)
        : componentName_(std::move(componentName)) {}

    // Returns how many components were found changed but unmarked (and marks them).
    std::size_t run(ecs::Registry& registry);
    // Called after transform propagation: a WorldTransform stamped later than `tick` was
    // written by a system (the animation's skeleton pass writes a joint's local and world
    // together), so its LocalTransform change is consistent, not unmarked.
    void notePropagated(ecs::Tick tick) { propagatedAt_ = tick; }

private:
    struct Seen {
        T value;
        std::uint32_t pass = 0;
        bool reported = false;
    };
    std::string componentName_;
    std::unordered_map<std::uint64_t, Seen> seen_;
    ecs::Tick checkedUpTo_ = 0;
    ecs::Tick propagatedAt_ = ecs::kNeverTick;
    std::uint32_t pass_ = 0;
};

// The name to show for an entity in a warning: its Name component, else its id.
std::string entityLabel(const ecs::Registry& registry, ecs::Entity e);

}  // namespace candela::runtime
