#include "candela/runtime/light_table.h"

#include <cmath>
#include <cstring>

#include "candela/content/components/light.h"
#include "candela/ecs/transform.h"

namespace candela::runtime {

namespace {

glm::vec3 unitColumn(const ecs::Mat4& m, int column, const glm::vec3& fallback) {
    glm::vec3 v(m(0, column), m(1, column), m(2, column));
    float length = glm::length(v);
    return length > 0.0f && std::isfinite(length) ? v / length : fallback;
}

// The slot group a light belongs in, in the order of the lighting pass's loops by class
// (render/src/passes/lighting/light_loops.h): points and spots without a size; spheres and
// tubes; rects and disks; then points, spots, spheres and tubes that cast, and rects and disks
// that cast. Cluster lists are in slot order, so each loop
// takes a run of a pixel's list with only its class's code (render/README.md "What a shader
// costs on lavapipe").
int slotGroup(const content::Light& light) {
    const bool area =
        light.type == content::LightType::Rect || light.type == content::LightType::Disk;
    if (area && light.castShadows) return 4;
    if (light.castShadows) return 3;
    if (area) return 2;
    return content::isPlainPunctualLight(light) ? 0 : 1;
}
constexpr int kSlotGroups = 5;

}  // namespace

render::LightInstance lightInstance(const content::Light& light, const ecs::Mat4& world) {
    render::LightInstance instance;
    instance.light = light;
    instance.position = glm::vec3(world(0, 3), world(1, 3), world(2, 3));
    instance.direction = -unitColumn(world, 2, {0.0f, 0.0f, 1.0f});
    instance.tubeAxis = unitColumn(world, 0, {1.0f, 0.0f, 0.0f});
    // A non-finite transform keeps the light in its slot but out of the picture.
    if (!std::isfinite(instance.position.x + instance.position.y + instance.position.z)) {
        instance.light.lumens = 0.0f;
        instance.light.lux = 0.0f;
        instance.position = glm::vec3(0.0f);
    }
    return instance;
}

LightTable::LightTable(ecs::Registry& registry) : registry_(registry) {
    auto markDirty = [this](ecs::Registry&, ecs::Entity) { structureDirty_ = true; };
    hooks_.push_back(registry.onAdd<content::Light>(markDirty));
    hooks_.push_back(registry.onRemove<content::Light>(markDirty));
    hooks_.push_back(registry.onAdd<ecs::WorldTransform>(markDirty));
    hooks_.push_back(registry.onRemove<ecs::WorldTransform>(markDirty));
}

LightTable::~LightTable() {
    for (ecs::HookId id : hooks_)
        registry_.disconnect(id);
}

void LightTable::rebuild() {
    lights_.clear();
    slotOfEntity_.clear();
    for (int group = 0; group < kSlotGroups; ++group) {
        registry_.view<const ecs::WorldTransform, const content::Light>().each(
            [&](ecs::Entity e, const ecs::WorldTransform& world, const content::Light& light) {
                if (slotGroup(light) != group) return;
                slotOfEntity_.emplace(e.bits(), uint32_t(lights_.size()));
                lights_.push_back(lightInstance(light, world.matrix));
            });
    }
}

void LightTable::update() {
    // Every change up to now is visited once: this call covers (seenUpTo_, upTo].
    const ecs::Tick upTo = registry_.advanceTick();
    changed_.clear();
    restructured_ = structureDirty_;
    if (structureDirty_) {
        rebuild();
        structureDirty_ = false;
    } else {
        registry_.view<const ecs::WorldTransform, const content::Light>().eachChangedSince(
            seenUpTo_,
            [&](ecs::Entity e, const ecs::WorldTransform& world, const content::Light& light) {
                auto it = slotOfEntity_.find(e.bits());
                if (it == slotOfEntity_.end()) return;
                // A light that changes group (starts casting, gets a size) moves slots.
                if (slotGroup(lights_[it->second].light) != slotGroup(light)) {
                    structureDirty_ = true;
                }
                lights_[it->second] = lightInstance(light, world.matrix);
                changed_.push_back(it->second);
            });
        if (structureDirty_) {
            changed_.clear();
            restructured_ = true;
            rebuild();
            structureDirty_ = false;
        }
    }
    seenUpTo_ = upTo;
}

}  // namespace candela::runtime
