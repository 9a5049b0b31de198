#pragma once
// --physics-debug: the physics world's lines (physics/physics_debug_lines.h) drawn as wires
// over the scene, each frame: colliders green, triggers yellow, contact points red. Wires are
// depth-tested like the rest of the scene and glow at a luminance the camera's exposure shows
// as bright, whatever the lighting.
#include <array>
#include <vector>

#include "candela/content/material.h"
#include "candela/content/wire.h"
#include "candela/physics/physics_debug_lines.h"
#include "candela/render/frame_scene.h"

namespace candela::runtime {

class PhysicsDebugView {
public:
    // Rebuilds the wires from `world` and appends their draws to `wires` (the frame's wire
    // draws, which then point into this view until the next call).
    void appendTo(const physics::PhysicsWorld& world, float ev100,
                  std::vector<render::WireDraw>& wires);

private:
    std::vector<physics::DebugLine> lines_;
    std::array<content::Wire, 3> wires_;  // by DebugLineKind
    std::array<content::Material, 3> materials_;
};

}  // namespace candela::runtime
