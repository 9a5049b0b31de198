#include "passes/volumetrics/light_proxies.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "lights/gpu_light_types.h"
#include "passes/volumetrics/light_bins.h"

namespace candela::render {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;
// Spots this wide or wider draw the sphere: the cone's base would outgrow it.
constexpr float kWidestConeProxy = 70.0f * kPi / 180.0f;
constexpr uint32_t kConeSegments = 12;

// Draw groups in drawing order: kind, then area lights, then whether the camera is inside.
constexpr uint32_t kProxyGroups = 12;
constexpr uint32_t groupIndex(LightProxyKind kind, bool area, bool holdsCamera) {
    return uint32_t(kind) * 4 + (area ? 2 : 0) + (holdsCamera ? 1 : 0);
}

}  // namespace

float sphereProxyScale() {
    return 1.0f / (std::cos(kPi / 8.0f) * std::cos(kPi / 6.0f));
}

float nearPlaneReach(const CameraView& camera) {
    // The near plane's corners lie near * |(1 / P00, 1 / P11, 1)| from the camera.
    const float x = camera.projection[0][0] != 0.0f ? 1.0f / camera.projection[0][0] : 0.0f;
    const float y = camera.projection[1][1] != 0.0f ? 1.0f / camera.projection[1][1] : 0.0f;
    return camera.nearPlane * std::sqrt(1.0f + x * x + y * y);
}

bool proxyHoldsCamera(const glm::vec3& centre, float radius, const CameraView& camera) {
    // Twice the reach and a relative slack: a volume a hair outside still draws back faces,
    // which is only slower.
    return glm::length(camera.position - centre) <= radius * 1.001f + 2.0f * nearPlaneReach(camera);
}

LightProxies buildLightProxies(std::span<const LightInstance> lights, std::span<const float> scales,
                               const CameraView& camera, uint32_t width, uint32_t height) {
    const LightBinLayout screen = volumeTileLayout(width, height);
    std::array<std::vector<uint32_t>, kProxyGroups> groups;
    LightProxies proxies;
    for (uint32_t i = 0; i < lights.size(); ++i) {
        if (i >= scales.size() || !(scales[i] > 0.0f)) continue;
        const LightInstance& instance = lights[i];
        const content::Light& light = instance.light;
        if (inEveryCluster(light)) {
            proxies.instances.push_back(i);  // the sun: the full-screen pass
            continue;
        }
        const float range = std::isfinite(light.attenuationRadius) ? light.attenuationRadius : 0.0f;
        if (!(range > 0.0f) || !std::isfinite(glm::dot(instance.position, instance.position))) {
            continue;  // reaches nothing (gpu_light.cpp gives it no intensity)
        }
        glm::uvec3 first, last;
        if (!binsCovered(lightVolumeBox(instance), camera, screen, first, last)) continue;
        const float outer = std::clamp(light.outerConeAngle, 0.0f, kPi / 2.0f);
        const bool cone = light.type == content::LightType::Spot && outer < kWidestConeProxy;
        // The proxy's bounding sphere about the light: the cone's reaches its base's corners.
        const float bound =
            cone ? range * std::sqrt(1.0f + std::pow(std::tan(outer) /
                                                         std::cos(kPi / float(kConeSegments)),
                                                     2.0f))
                 : range * sphereProxyScale();
        // Rect and disk lights scatter by their form factor (volumetric_medium.glsl), in a
        // variant of their own; their volume is the half of the range sphere in front of them
        // (zero behind their plane), drawn as a hemisphere. The camera behind that plane (by
        // more than the near plane reaches) is outside it.
        const bool area =
            light.type == content::LightType::Rect || light.type == content::LightType::Disk;
        const LightProxyKind kind = area   ? LightProxyKind::Hemisphere
                                    : cone ? LightProxyKind::Cone
                                           : LightProxyKind::Sphere;
        bool holds = proxyHoldsCamera(instance.position, bound, camera);
        if (area && holds && glm::length(instance.direction) > 0.0f) {
            const float ahead =
                glm::dot(camera.position - instance.position, glm::normalize(instance.direction));
            holds = ahead > -2.0f * nearPlaneReach(camera);
        }
        groups[groupIndex(kind, area, holds)].push_back(i);
    }
    proxies.fullScreen = uint32_t(proxies.instances.size());
    for (uint32_t g = 0; g < groups.size(); ++g) {
        if (groups[g].empty()) continue;
        LightProxyDraw draw;
        draw.kind = LightProxyKind(g / 4);
        draw.areaLights = (g & 2) != 0;
        draw.holdsCamera = (g & 1) != 0;
        draw.firstInstance = uint32_t(proxies.instances.size());
        draw.instanceCount = uint32_t(groups[g].size());
        proxies.instances.insert(proxies.instances.end(), groups[g].begin(), groups[g].end());
        proxies.draws.push_back(draw);
    }
    return proxies;
}

}  // namespace candela::render
