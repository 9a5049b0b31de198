#pragma once
// A glTF node's "extras": {"rigidBody": {...}, "collider": {...}}, spelled and checked exactly
// as a scene file's (physics/README.md), so an artist's Blender custom properties and a scene
// file describe bodies alike.
#include <optional>
#include <string>

#include "candela/content/components/collider.h"
#include "candela/content/components/rigid_body.h"
#include "candela/content/diagnostics.h"

namespace candela::content {

struct PhysicsExtras {
    std::optional<RigidBody> rigidBody;
    std::optional<Collider> collider;
};

// `extrasJson` is the node's extras as JSON text; problems are reported against `file` and
// `element` (e.g. "nodes[3]") plus the key ("nodes[3].extras/collider/radius").
PhysicsExtras readPhysicsExtras(const std::string& extrasJson, const std::string& file,
                                const std::string& element, Diagnostics& diagnostics);

}  // namespace candela::content
