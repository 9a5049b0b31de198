#include "unmarked_changes.h"

#include <cstdio>
#include <cstring>
#include <type_traits>
#include <unordered_set>
#include <vector>

#include "candela/content/components/animation.h"
#include "candela/content/components/light.h"
#include "candela/content/components/name.h"
#include "candela/ecs/transform.h"
#include "candela/ecs/view.h"

namespace candela::runtime {

std::string entityLabel(const ecs::Registry& registry, ecs::Entity e) {
    if (const auto* name = registry.tryGet<content::Name>(e); name && !name->value.empty()) {
        return "'" + name->value + "'";
    }
    return "#" + std::to_string(e.bits());
}

template <class T>
std::size_t UnmarkedChangeCheck<T>::run(ecs::Registry& registry) {
    static_assert(std::is_trivially_copyable_v<T>, "compared byte for byte");
    // Changes stamped after the previous run have ticks above checkedUpTo_.
    const ecs::Tick since = checkedUpTo_;
    checkedUpTo_ = registry.advanceTick();
    ++pass_;
    std::vector<ecs::Entity> unmarked;
    // Joints whose LocalTransform the animation's skeleton pass writes without a stamp and
    // whose WorldTransform it leaves to its own buffer (AnimationPlayer::writeJointWorlds
    // false): the skins are built from them, propagation recomputes them from these locals
    // when an ancestor moves. Consistent, though neither is stamped.
    std::unordered_set<std::uint64_t> poseOwnedJoints;
    if constexpr (std::is_same_v<T, ecs::LocalTransform>) {
        registry.view<const content::Skin>().each([&](ecs::Entity, const content::Skin& skin) {
            if (!skin.worldsSkippedByPose) return;
            for (const ecs::Entity joint : skin.joints)
                poseOwnedJoints.insert(joint.bits());
        });
    }
    registry.view<const T>().each([&](ecs::Entity e, const T& value) {
        auto [it, added] = seen_.try_emplace(e.bits());
        Seen& seen = it->second;
        seen.pass = pass_;
        if (added) {
            std::memcpy(&seen.value, &value, sizeof(T));  // bytes, padding included
            return;
        }
        if (std::memcmp(&seen.value, &value, sizeof(T)) == 0) return;
        std::memcpy(&seen.value, &value, sizeof(T));
        if (registry.changedSince<T>(e, since)) return;  // marked: the frame sees it
        if constexpr (std::is_same_v<T, ecs::LocalTransform>) {
            // Written together with its WorldTransform after the last propagation (the
            // animation's skeleton pass does that for joints only skins read): consistent.
            if (propagatedAt_ != ecs::kNeverTick &&
                registry.changedSince<ecs::WorldTransform>(e, propagatedAt_))
                return;
            if (poseOwnedJoints.contains(e.bits())) return;
        }
        unmarked.push_back(e);
        if (!seen.reported) {
            seen.reported = true;
            std::fprintf(stderr,
                         "candela: warning: the %s of entity %s was changed without "
                         "markChanged<%s>() (or patch()); updated it now (shown once per "
                         "entity)\n",
                         componentName_.c_str(), entityLabel(registry, e).c_str(),
                         componentName_.c_str());
        }
    });
    // Marking is not structural, but done outside the walk all the same.
    for (ecs::Entity e : unmarked)
        registry.markChanged<T>(e);
    // Entities that lost T (or were destroyed) are forgotten.
    std::erase_if(seen_, [&](const auto& entry) { return entry.second.pass != pass_; });
    return unmarked.size();
}

template class UnmarkedChangeCheck<content::Light>;
template class UnmarkedChangeCheck<ecs::LocalTransform>;

}  // namespace candela::runtime
