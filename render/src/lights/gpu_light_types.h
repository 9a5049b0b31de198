#pragma once
// The render side of "one place per light type" (README "Adding a light type"): how each
// content::LightType is encoded for the shaders, which shader variant switch it needs, and how
// clustered culling bounds it, on the CPU (clustered/light_bounds.cpp, the frustum pre-pass)
// and the GPU (shaders/common/light_cluster_tests.glsl). The content side's table is
// content/light_types.h; the shading is lights.glsl's evaluateLight.
#include <array>
#include <cstddef>
#include <cstdint>

#include "candela/content/light_types.h"
#include "common/light_types.h"
#include "common/specialization_ids.h"

namespace candela::render {

// What clustered culling bounds a light by; the GLSL reads the same kinds by type code
// (LIGHT_BOUNDS_* in common/light_types.h).
enum class ClusterBounds : uint8_t {
    // In every cluster's list (directional): listed once, ahead of the local lists.
    Everywhere = LIGHT_BOUNDS_EVERYWHERE,
    // The falloff sphere (eq. 9's window) around the source; a capsule for a tube.
    Falloff = LIGHT_BOUNDS_FALLOFF,
    // The spot cone out to the falloff radius (spots wider than ~80 degrees and tubes are
    // bounded as Falloff).
    Cone = LIGHT_BOUNDS_CONE,
    // One-sided area lights (rect, disk): the falloff sphere around the centre cut by the
    // half-space in front of the light's plane.
    HalfSpace = LIGHT_BOUNDS_HALF_SPACE,
};

// Rect: (width, height); disk: (radius, radius). Non-finite or negative sizes become 0 (a
// light of zero area, which packLight makes emit nothing).
inline void encodeRectShape(const content::Light& light, float shape[2]) {
    shape[0] = light.width >= 0.0f && light.width < 1e30f ? light.width : 0.0f;
    shape[1] = light.height >= 0.0f && light.height < 1e30f ? light.height : 0.0f;
}
inline void encodeDiskShape(const content::Light& light, float shape[2]) {
    const float r = light.sourceRadius;
    shape[0] = shape[1] = r >= 0.0f && r < 1e30f ? r : 0.0f;
}

inline constexpr uint32_t kNoSpecialization = ~0u;

struct GpuLightTypeInfo {
    content::LightType type;
    uint32_t gpuType;  // LIGHT_TYPE_* (common/light_types.h): what lights.glsl dispatches on
    ClusterBounds bounds;
    // The specialization constant that compiles the type's shading in (SPEC_*), and its name
    // in --stats "features"; kNoSpecialization / nullptr for code every variant has.
    uint32_t specialization;
    const char* feature;
    // Parameters of the type's shape beyond the common record (position, direction, tube axis,
    // source radius and length, spot cone), e.g. a rectangle's width and height: written to
    // GpuLight::shape, read as Light.shape in lights.glsl. nullptr: none (zeros).
    void (*encodeShape)(const content::Light& light, float shape[2]);
};

// One row per content::LightType, in enumerator order (checked below).
inline constexpr std::array<GpuLightTypeInfo, content::kLightTypeCount> kGpuLightTypeTable{{
    {content::LightType::Point, LIGHT_TYPE_POINT, ClusterBounds::Falloff, kNoSpecialization,
     nullptr, nullptr},
    {content::LightType::Spot, LIGHT_TYPE_SPOT, ClusterBounds::Cone, SPEC_SPOT_LIGHTS_ENABLED,
     "lights_spot", nullptr},
    {content::LightType::Directional, LIGHT_TYPE_DIRECTIONAL, ClusterBounds::Everywhere,
     kNoSpecialization, nullptr, nullptr},
    {content::LightType::Rect, LIGHT_TYPE_RECT, ClusterBounds::HalfSpace, SPEC_RECT_LIGHTS_ENABLED,
     "lights_rect", encodeRectShape},
    {content::LightType::Disk, LIGHT_TYPE_DISK, ClusterBounds::HalfSpace, SPEC_DISK_LIGHTS_ENABLED,
     "lights_disk", encodeDiskShape},
}};

constexpr bool gpuLightTypeTableIsComplete() {
    // The shaders' view of the bounds, by type code (common/light_types.h).
    constexpr uint32_t kShaderBounds[] = {LIGHT_BOUNDS_BY_TYPE};
    if (std::size(kShaderBounds) != kGpuLightTypeTable.size() ||
        LIGHT_TYPE_COUNT != kGpuLightTypeTable.size()) {
        return false;
    }
    for (std::size_t i = 0; i < kGpuLightTypeTable.size(); ++i) {
        if (content::lightTypeIndex(kGpuLightTypeTable[i].type) != i) return false;
        const uint32_t code = kGpuLightTypeTable[i].gpuType;
        if (code >= LIGHT_TYPE_COUNT ||
            kShaderBounds[code] != uint32_t(kGpuLightTypeTable[i].bounds)) {
            return false;
        }
        for (std::size_t j = 0; j < i; ++j) {  // lights.glsl tells the types apart by code
            if (kGpuLightTypeTable[j].gpuType == kGpuLightTypeTable[i].gpuType) return false;
        }
    }
    return true;
}
static_assert(gpuLightTypeTableIsComplete(),
              "kGpuLightTypeTable needs one row per content::LightType, in enumerator order, "
              "each with its own LIGHT_TYPE_* code below LIGHT_TYPE_COUNT and the cluster bounds "
              "LIGHT_BOUNDS_BY_TYPE gives that code (common/light_types.h)");

constexpr const GpuLightTypeInfo& gpuLightType(content::LightType type) {
    return kGpuLightTypeTable[content::lightTypeIndex(type)];
}

// Directional lights: no position and no falloff, so in every cluster.
constexpr bool inEveryCluster(const content::Light& light) {
    return gpuLightType(light.type).bounds == ClusterBounds::Everywhere;
}

}  // namespace candela::render
