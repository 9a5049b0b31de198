#pragma once
// Conversions between the engine's transform math (ecs/transform_math.h) and Bullet's.
#include <LinearMath/btTransform.h>

#include "candela/ecs/transform_math.h"

namespace candela::physics {

inline btVector3 toBullet(ecs::Vec3 v) {
    return {v.x, v.y, v.z};
}
inline btQuaternion toBullet(ecs::Quat q) {
    return {q.x, q.y, q.z, q.w};
}
inline btTransform toBullet(ecs::Vec3 position, ecs::Quat rotation) {
    return btTransform(toBullet(rotation), toBullet(position));
}
inline ecs::Vec3 fromBullet(const btVector3& v) {
    return {v.x(), v.y(), v.z()};
}
inline ecs::Quat fromBullet(const btQuaternion& q) {
    return {q.x(), q.y(), q.z(), q.w()};
}

}  // namespace candela::physics
