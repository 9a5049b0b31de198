#pragma once
// Exact segment intersections with Bullet's primitive shapes in their own space (Bullet's
// own ray test for convex shapes stops within about a centimetre of the surface).
#include <btBulletCollisionCommon.h>

#include <optional>

namespace candela::physics {

struct LocalHit {
    btScalar fraction = 0;  // along the segment, 0..1
    btVector3 normal;       // unit, in the shape's space
};

// Spheres, boxes, Y capsules, Y cylinders and convex hulls with their faces computed.
bool isPrimitive(const btCollisionShape& shape);

// Where the segment from..to first enters the shape from outside; nullopt when it misses,
// starts inside or the shape is not a primitive.
std::optional<LocalHit> intersectPrimitive(const btCollisionShape& shape, const btVector3& from,
                                           const btVector3& to);

}  // namespace candela::physics
