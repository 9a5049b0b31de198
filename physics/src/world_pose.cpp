#include "world_pose.h"

#include <LinearMath/btMatrix3x3.h>

#include <cmath>

#include "bullet_math.h"
#include "candela/ecs/affine_multiply.h"
#include "candela/ecs/hierarchy.h"
#include "candela/ecs/transform.h"

namespace candela::physics {

WorldPose decompose(const ecs::Mat4& m) {
    WorldPose pose;
    pose.position = m.translationPart();
    btVector3 axes[3];
    float scale[3];
    for (int c = 0; c < 3; ++c) {
        axes[c] = btVector3(m.m[c * 4 + 0], m.m[c * 4 + 1], m.m[c * 4 + 2]);
        scale[c] = static_cast<float>(axes[c].length());
        if (scale[c] > 0.0f) axes[c] /= scale[c];
    }
    pose.scale = {scale[0], scale[1], scale[2]};
    const btMatrix3x3 basis(axes[0].x(), axes[1].x(), axes[2].x(),  //
                            axes[0].y(), axes[1].y(), axes[2].y(),  //
                            axes[0].z(), axes[1].z(), axes[2].z());
    btQuaternion rotation;
    basis.getRotation(rotation);
    pose.rotation = ecs::normalize(fromBullet(rotation));
    return pose;
}

std::optional<WorldPose> poseRelativeTo(const ecs::Registry& registry, ecs::Entity entity,
                                        ecs::Entity owner) {
    const auto* local = registry.tryGet<ecs::LocalTransform>(entity);
    if (!local) return std::nullopt;
    ecs::Mat4 relative = local->matrix();
    for (ecs::Entity link = ecs::parentOf(registry, entity); link != owner;
         link = ecs::parentOf(registry, link)) {
        const auto* linkLocal =
            link.isNull() ? nullptr : registry.tryGet<ecs::LocalTransform>(link);
        if (!linkLocal) return std::nullopt;
        ecs::Mat4 composed;
        ecs::multiplyByAffine(linkLocal->matrix(), relative, composed);
        relative = composed;
    }
    return decompose(relative);
}

std::optional<WorldPose> worldPoseOf(const ecs::Registry& registry, ecs::Entity entity) {
    const auto* local = registry.tryGet<ecs::LocalTransform>(entity);
    const ecs::Entity parent = ecs::parentOf(registry, entity);
    const auto* parentWorld =
        parent.isNull() ? nullptr : registry.tryGet<ecs::WorldTransform>(parent);
    if (local && !parentWorld) return WorldPose{local->position, local->rotation, local->scale};
    if (local && parentWorld) {
        ecs::Mat4 world;
        ecs::multiplyByAffine(parentWorld->matrix, local->matrix(), world);
        return decompose(world);
    }
    if (const auto* world = registry.tryGet<ecs::WorldTransform>(entity)) {
        return decompose(world->matrix);
    }
    return std::nullopt;
}

void worldToLocal(const ecs::Registry& registry, ecs::Entity entity, ecs::Vec3 worldPosition,
                  ecs::Quat worldRotation, ecs::Vec3& localPosition, ecs::Quat& localRotation) {
    const ecs::Entity parent = ecs::parentOf(registry, entity);
    const auto* parentWorld =
        parent.isNull() ? nullptr : registry.tryGet<ecs::WorldTransform>(parent);
    if (!parentWorld) {
        localPosition = worldPosition;
        localRotation = worldRotation;
        return;
    }
    const WorldPose p = decompose(parentWorld->matrix);
    const ecs::Quat inverse = ecs::conjugate(p.rotation);
    const ecs::Vec3 offset = ecs::rotate(inverse, worldPosition - p.position);
    const auto divide = [](float v, float s) { return s != 0.0f ? v / s : v; };
    localPosition = {divide(offset.x, p.scale.x), divide(offset.y, p.scale.y),
                     divide(offset.z, p.scale.z)};
    localRotation = ecs::normalize(inverse * worldRotation);
}

}  // namespace candela::physics
