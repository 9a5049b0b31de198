#pragma once
// Turns the pairs touching after each step into Begin/Stay/End events per update.
#include <cstdint>
#include <map>
#include <vector>

#include "candela/physics/physics_events.h"

namespace candela::physics {

struct BodyPair {
    std::uint64_t a = 0;  // entity bits
    std::uint64_t b = 0;
    friend auto operator<=>(const BodyPair&, const BodyPair&) = default;
};

struct Touch {
    ecs::Vec3 point{};
    ecs::Vec3 normal{};
    float impulse = 0.0f;
};

class ContactTracker {
public:
    // Forgets the phases the previous update reported.
    void beginUpdate();
    // The pairs touching at the end of one step.
    void observeStep(const std::map<BodyPair, Touch>& touching);
    // The update's events in pair order, each pair's phases in the order Begin, Stay, End.
    void emitContacts(std::vector<ContactEvent>& out) const;
    void emitTriggers(std::vector<TriggerEvent>& out) const;

private:
    struct Seen {
        bool began = false;
        bool stayed = false;
        bool ended = false;
        Touch touch;
    };
    std::map<BodyPair, Touch> touching_;  // as of the last step
    std::map<BodyPair, Seen> seen_;       // this update
};

}  // namespace candela::physics
