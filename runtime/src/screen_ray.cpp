#include "candela/runtime/screen_ray.h"

#include <cmath>

#include "candela/content/components/camera.h"
#include "candela/ecs/transform.h"

namespace candela::runtime {
namespace {

ecs::Vec3 unit(ecs::Vec3 v) {
    const float length = ecs::length(v);
    return length > 0.0f ? v * (1.0f / length) : v;
}

bool finite(ecs::Vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

std::optional<Ray> screenRay(const ecs::Registry& registry, ecs::Entity camera, float x, float y,
                             std::uint32_t width, std::uint32_t height) {
    if (width == 0 || height == 0 || !registry.valid(camera)) return std::nullopt;
    const auto* lens = registry.tryGet<content::Camera>(camera);
    const auto* world = registry.tryGet<ecs::WorldTransform>(camera);
    if (!lens || !world) return std::nullopt;
    // The view's axes as frame extraction builds them: -Z forward, +Y up, orthonormalised.
    const ecs::Mat4& m = world->matrix;
    const ecs::Vec3 forward = unit(ecs::Vec3{-m.m[8], -m.m[9], -m.m[10]});
    const ecs::Vec3 right = unit(ecs::cross(forward, ecs::Vec3{m.m[4], m.m[5], m.m[6]}));
    const ecs::Vec3 up = ecs::cross(right, forward);
    const ecs::Vec3 origin = m.translationPart();
    if (!finite(forward) || !finite(right) || !finite(origin) || ecs::length(right) == 0.0f) {
        return std::nullopt;
    }
    const float tanHalf = std::tan(0.5f * lens->verticalFov);
    const float aspect = float(width) / float(height);
    const float ndcX = 2.0f * x / float(width) - 1.0f;
    const float ndcY = 1.0f - 2.0f * y / float(height);
    const ecs::Vec3 direction =
        unit(forward + right * (ndcX * tanHalf * aspect) + up * (ndcY * tanHalf));
    if (!finite(direction)) return std::nullopt;
    return Ray{origin, direction};
}

}  // namespace candela::runtime
