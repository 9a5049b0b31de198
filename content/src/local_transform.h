#pragma once
// A model's or scene file's node transform as the ECS component instantiated entities carry.
#include <candela/ecs/transform.h>

#include "candela/content/model.h"

namespace candela::content {

inline ecs::LocalTransform toLocalTransform(const Transform& t) {
    ecs::LocalTransform local;
    local.position = {t.translation[0], t.translation[1], t.translation[2]};
    local.rotation = {t.rotation[0], t.rotation[1], t.rotation[2], t.rotation[3]};
    local.scale = {t.scale[0], t.scale[1], t.scale[2]};
    return local;
}

}  // namespace candela::content
