#include "candela/content/model_lookup.h"

#include "candela/content/components/animation.h"
#include "candela/content/components/name.h"
#include "candela/ecs/hierarchy.h"

namespace candela::content {
namespace {

template <class Match>
ecs::Entity findUnder(const ecs::Registry& registry, ecs::Entity root, Match&& match) {
    if (!registry.valid(root)) return ecs::kNullEntity;
    if (match(root)) return root;
    for (ecs::Entity e : ecs::descendantsOf(registry, root)) {
        if (match(e)) return e;
    }
    return ecs::kNullEntity;
}

}  // namespace

ecs::Entity findNamed(const ecs::Registry& registry, ecs::Entity root, std::string_view name) {
    return findUnder(registry, root, [&](ecs::Entity e) {
        const auto* n = registry.tryGet<Name>(e);
        return n && n->value == name;
    });
}

ecs::Entity findAnimationPlayer(const ecs::Registry& registry, ecs::Entity root) {
    return findUnder(registry, root,
                     [&](ecs::Entity e) { return registry.has<AnimationPlayer>(e); });
}

}  // namespace candela::content
