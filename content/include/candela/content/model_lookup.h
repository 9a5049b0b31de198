#pragma once
// A loaded model's entities by what a game asks for, without walking the hierarchy by hand:
//
//   const ecs::Entity fox = world.spawn("fox");
//   world.loadGltf("Fox.glb", diagnostics, fox);
//   ecs::Entity head = findNamed(world.registry, fox, "b_Head_05");
//   ecs::Entity animated = findAnimationPlayer(world.registry, fox);
//   world.registry.get<AnimationPlayer>(animated).crossfade(run, 0.25f);
#include <string_view>

#include "candela/ecs/entity.h"
#include "candela/ecs/registry.h"

namespace candela::content {

// `root` itself or the first of its descendants (parents before children, siblings in order)
// whose Name is `name`; kNullEntity when none is.
ecs::Entity findNamed(const ecs::Registry& registry, ecs::Entity root, std::string_view name);

// `root` itself or the first of its descendants holding an AnimationPlayer (the entity a
// model's clips play on); kNullEntity when none does.
ecs::Entity findAnimationPlayer(const ecs::Registry& registry, ecs::Entity root);

}  // namespace candela::content
