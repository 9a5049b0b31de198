#include "gpu_light.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "candela/content/component_validation.h"
#include "lights/gpu_light_types.h"

namespace candela::render {

namespace {

float finiteOr(float value, float fallback) {
    return std::isfinite(value) ? value : fallback;
}

void store(float out[3], const glm::vec3& v) {
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
}

glm::vec3 unitOr(const glm::vec3& v, const glm::vec3& fallback) {
    float lengthSq = glm::dot(v, v);
    if (!std::isfinite(lengthSq) || lengthSq < 1e-20f) return fallback;
    return v / std::sqrt(lengthSq);
}

}  // namespace

GpuLight packLight(const LightInstance& instance, uint32_t textureSlot) {
    const content::Light& l = instance.light;
    GpuLight g{};
    store(g.position, instance.position);
    float radius = std::max(finiteOr(l.attenuationRadius, 0.0f), 0.0f);
    g.invAttenuationRadius = 1.0f / std::max(radius, 1e-6f);
    const bool inLux = content::lightTypeInfo(l.type).power == content::LightPower::Lux;
    float photometric = inLux ? l.lux : l.lumens / (4.0f * std::numbers::pi_v<float>);  // lm -> cd
    const bool area = content::isAreaLight(l.type);
    if (area) {
        // Lambertian one-sided emitter: luminance (cd/m^2) = lumens / (pi area); no area (or a
        // non-finite one) emits nothing.
        const float emitting = content::emitterArea(l);
        // A constant-intensity emitter: intensity per square metre (cd/m^2) = lumens / (2 pi
        // area), its flux spread evenly over the hemisphere in front.
        const float perSteradian =
            l.emission == content::AreaLightEmission::ConstantIntensity ? 2.0f : 1.0f;
        photometric = emitting > 0.0f && std::isfinite(emitting)
                          ? l.lumens / (perSteradian * std::numbers::pi_v<float> * emitting)
                          : 0.0f;
    }
    photometric = std::max(finiteOr(photometric, 0.0f), 0.0f);
    // A zero attenuation radius means the light reaches nothing.
    if (radius == 0.0f && !inEveryCluster(l)) photometric = 0.0f;
    // Capped in double at the brightest the loaders and the editor let through, so a light set
    // directly by code cannot overflow to Inf and make NaN texels either.
    constexpr double kMaxIntensity =
        double(content::kMaxLightColorChannel) *
        std::max(double(content::kMaxLux), double(content::kMaxLumens) / (4.0 * std::numbers::pi));
    for (int i = 0; i < 3; ++i) {
        const double channel = double(std::max(finiteOr(l.color[i], 0.0f), 0.0f)) * photometric;
        g.intensity[i] = float(std::min(channel, kMaxIntensity));
    }
    g.sourceRadius = std::max(finiteOr(l.sourceRadius, 0.0f), 0.0f);
    // Area lights have no tube (the culling shaders read sourceLength > 0 as a capsule).
    g.sourceLength = area ? 0.0f : std::max(finiteOr(l.sourceLength, 0.0f), 0.0f);
    store(g.direction, unitOr(instance.direction, {0.0f, 0.0f, -1.0f}));
    store(g.tubeAxis, unitOr(instance.tubeAxis, {1.0f, 0.0f, 0.0f}));
    g.type = gpuLightType(l.type).gpuType;
    if (const auto encodeShape = gpuLightType(l.type).encodeShape) encodeShape(l, g.shape);
    float outer = std::clamp(finiteOr(l.outerConeAngle, 0.0f), 0.0f, 1.5707963f);
    float inner = std::clamp(finiteOr(l.innerConeAngle, 0.0f), 0.0f, outer);
    float cosOuter = std::cos(outer);
    float cosInner = std::cos(inner);
    g.spotScale = 1.0f / std::max(cosInner - cosOuter, 1e-4f);
    g.spotOffset = -cosOuter * g.spotScale;
    if (area) {
        // No cone: spotOffset carries the per-light quality and emission, spotScale 1 + a textured
        // rect's atlas slot (area_lights.glsl); culling reads neither for a half-space bound.
        g.spotScale = 1.0f + (l.type == content::LightType::Rect ? float(textureSlot) : 0.0f);
        // + 4 for a constant-intensity emitter (kAreaEmissionConstantIntensity).
        g.spotOffset =
            float(uint32_t(l.quality) +
                  (l.emission == content::AreaLightEmission::ConstantIntensity ? 4u : 0u));
    }
    // Point and spot lights have no shape parameters: shape[0] carries the quality for their
    // sphere and tube (lights.glsl localLightRepresentative).
    if (l.type == content::LightType::Point || l.type == content::LightType::Spot) {
        g.shape[0] = float(uint32_t(l.quality));
    }
    return g;
}

}  // namespace candela::render
