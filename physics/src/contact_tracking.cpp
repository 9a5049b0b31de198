#include "contact_tracking.h"

#include <algorithm>

namespace candela::physics {

void ContactTracker::beginUpdate() {
    seen_.clear();
}

void ContactTracker::observeStep(const std::map<BodyPair, Touch>& touching) {
    for (const auto& [pair, touch] : touching) {
        Seen& seen = seen_[pair];
        if (touching_.contains(pair)) {
            seen.stayed = true;
        } else {
            seen.began = true;
        }
        const float impulse = std::max(seen.touch.impulse, touch.impulse);
        seen.touch = touch;
        seen.touch.impulse = impulse;
    }
    for (const auto& [pair, touch] : touching_) {
        if (!touching.contains(pair)) seen_[pair].ended = true;
    }
    touching_ = touching;
}

void ContactTracker::emitContacts(std::vector<ContactEvent>& out) const {
    for (const auto& [pair, seen] : seen_) {
        const auto emit = [&](ContactPhase phase) {
            out.push_back({ecs::Entity::fromBits(pair.a), ecs::Entity::fromBits(pair.b), phase,
                           seen.touch.point, seen.touch.normal, seen.touch.impulse});
        };
        if (seen.began) emit(ContactPhase::Begin);
        if (seen.stayed) emit(ContactPhase::Stay);
        if (seen.ended) emit(ContactPhase::End);
    }
}

void ContactTracker::emitTriggers(std::vector<TriggerEvent>& out) const {
    for (const auto& [pair, seen] : seen_) {
        const auto emit = [&](ContactPhase phase) {
            out.push_back({ecs::Entity::fromBits(pair.a), ecs::Entity::fromBits(pair.b), phase});
        };
        if (seen.began) emit(ContactPhase::Begin);
        if (seen.stayed) emit(ContactPhase::Stay);
        if (seen.ended) emit(ContactPhase::End);
    }
}

}  // namespace candela::physics
