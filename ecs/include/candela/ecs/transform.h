#pragma once
// Transform components. LocalTransform is what gameplay and the content loader write (relative
// to the parent, see hierarchy.h); WorldTransform is derived by propagateTransforms() and is
// what the renderer reads. Write LocalTransform through registry.patch/replace (or call
// markChanged) so propagation sees the change.
#include <candela/ecs/transform_math.h>

namespace candela::ecs {

struct LocalTransform {
    Vec3 position{};
    Quat rotation{};
    Vec3 scale{1.0f, 1.0f, 1.0f};

    Mat4 matrix() const { return Mat4::fromTranslationRotationScale(position, rotation, scale); }
};

struct WorldTransform {
    Mat4 matrix{};

    Vec3 position() const { return matrix.translationPart(); }
};

}  // namespace candela::ecs
