#pragma once
// The scene's lights as one dense array kept in step with the ECS. Entities with Light and
// WorldTransform own a slot; when either component changes only that slot is rewritten (ECS
// change ticks), and adding or removing a light rebuilds the table (on-add/on-remove hooks).
// Slots come in groups: points and spots without a size, then the other lights without
// shadows, then the lights that cast; every cluster list (in slot order) follows them, and the
// lighting pass walks each group with only its code. A light that changes group rebuilds the
// table.
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "candela/ecs/registry.h"
#include "candela/ecs/transform_math.h"
#include "candela/render/frame_scene.h"

namespace candela::runtime {

class LightTable {
public:
    explicit LightTable(ecs::Registry& registry);
    ~LightTable();
    LightTable(const LightTable&) = delete;
    LightTable& operator=(const LightTable&) = delete;

    // Brings the table up to date with the registry.
    void update();

    const std::vector<render::LightInstance>& lights() const { return lights_; }
    // Slots rewritten by the last update(); all of them when restructured() is true.
    const std::vector<uint32_t>& changedSlots() const { return changed_; }
    bool restructured() const { return restructured_; }

private:
    void rebuild();

    ecs::Registry& registry_;
    std::vector<ecs::HookId> hooks_;
    std::vector<render::LightInstance> lights_;
    std::unordered_map<uint64_t, uint32_t> slotOfEntity_;
    std::vector<uint32_t> changed_;
    ecs::Tick seenUpTo_ = 0;
    bool structureDirty_ = true;
    bool restructured_ = true;
};

// A light component at a world transform, as the renderer takes it (light axes from the
// transform: spots and directional lights shine along -Z, tubes lie along +X).
render::LightInstance lightInstance(const content::Light& light, const ecs::Mat4& world);

}  // namespace candela::runtime
