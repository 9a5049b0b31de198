#include "physics_debug_view.h"

#include "candela/render/renderer.h"

namespace candela::runtime {
namespace {

constexpr float kWireRadius = 0.006f;  // metres; the wire pass keeps it at least a pixel wide
// Luminance times exposure: well above mid grey, below what bloom smears.
constexpr float kExposedBrightness = 3.0f;
constexpr std::array<std::array<float, 3>, 3> kColours{{
    {0.1f, 1.0f, 0.2f},   // colliders
    {1.0f, 0.85f, 0.1f},  // triggers
    {1.0f, 0.1f, 0.1f},   // contacts
}};

}  // namespace

void PhysicsDebugView::appendTo(const physics::PhysicsWorld& world, float ev100,
                                std::vector<render::WireDraw>& wires) {
    physics::debugLines(world, lines_);
    for (content::Wire& wire : wires_) {
        wire.positions.clear();
        wire.segments.clear();
        wire.radius = kWireRadius;
    }
    for (const physics::DebugLine& line : lines_) {
        content::Wire& wire = wires_[static_cast<std::size_t>(line.kind)];
        const auto first = static_cast<std::uint32_t>(wire.positions.size());
        wire.positions.push_back({line.from.x, line.from.y, line.from.z});
        wire.positions.push_back({line.to.x, line.to.y, line.to.z});
        wire.segments.push_back(first);
        wire.segments.push_back(first + 1);
    }
    const float luminance = kExposedBrightness / render::exposureFromEv100(ev100);
    for (std::size_t kind = 0; kind < wires_.size(); ++kind) {
        if (wires_[kind].segments.empty()) continue;
        content::Material& material = materials_[kind];
        material.shadingModel = content::ShadingModel::Unlit;
        material.baseColorFactor = {0, 0, 0, 1};
        material.emissiveFactor = kColours[kind];
        material.emissiveStrength = luminance;
        wires.push_back({&wires_[kind], &material, glm::mat4(1.0f)});
    }
}

}  // namespace candela::runtime
