#include "candela/physics/physics_queries.h"

#include <BulletCollision/BroadphaseCollision/btBroadphaseInterface.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "bullet_math.h"
#include "physics_world_impl.h"
#include "ray_shape_intersection.h"

namespace candela::physics {
namespace {

bool passes(const QueryFilter& filter, const btCollisionObject* object) {
    const BodyRecord* record = recordOf(object);
    if (!record || record->entity == filter.ignore) return false;
    if (record->trigger() && !filter.triggers) return false;
    return (record->collider.layer & filter.layers) != 0;
}

// The colliders whose bounding boxes the ray crosses (Bullet's broadphase).
struct RayCandidates final : btBroadphaseRayCallback {
    // The ray as the broadphase's box tests take it.
    RayCandidates(const btVector3& from, const btVector3& to) {
        const btVector3 direction = (to - from).normalized();
        for (int i = 0; i < 3; ++i) {
            m_rayDirectionInverse[i] =
                direction[i] == 0 ? btScalar(BT_LARGE_FLOAT) : 1 / direction[i];
            m_signs[i] = m_rayDirectionInverse[i] < 0;
        }
        m_lambda_max = direction.dot(to - from);
    }
    std::vector<const btCollisionObject*> objects;
    bool process(const btBroadphaseProxy* proxy) override {
        objects.push_back(static_cast<const btCollisionObject*>(proxy->m_clientObject));
        return true;
    }
};

struct Entry {
    btScalar fraction = 0;
    btVector3 normal;
    int child = -1;  // which child of a compound shape; -1: not a compound
};

// Where the segment from..to enters `shape` at `pose`, as a fraction of its length: exact for
// the primitives and hulls, Bullet's ray test for triangle meshes.
std::optional<Entry> enterShape(const btCollisionObject& object, const btCollisionShape& shape,
                                const btTransform& pose, const btVector3& from,
                                const btVector3& to) {
    const btTransform inverse = pose.inverse();
    if (auto local = intersectPrimitive(shape, inverse(from), inverse(to))) {
        return Entry{local->fraction, pose.getBasis() * local->normal};
    }
    if (isPrimitive(shape)) return std::nullopt;
    btCollisionWorld::ClosestRayResultCallback result(from, to);
    btCollisionWorld::rayTestSingle(btTransform(btQuaternion::getIdentity(), from),
                                    btTransform(btQuaternion::getIdentity(), to),
                                    const_cast<btCollisionObject*>(&object),
                                    const_cast<btCollisionShape*>(&shape), pose, result);
    if (!result.hasHit()) return std::nullopt;
    return Entry{result.m_closestHitFraction, result.m_hitNormalWorld.normalized()};
}

// A compound's nearest child entered, so a hit names the part's entity.
std::optional<Entry> enterFraction(const btCollisionObject& object, const btVector3& from,
                                   const btVector3& to) {
    const btCollisionShape& shape = *object.getCollisionShape();
    if (shape.getShapeType() != COMPOUND_SHAPE_PROXYTYPE) {
        return enterShape(object, shape, object.getWorldTransform(), from, to);
    }
    const auto& compound = static_cast<const btCompoundShape&>(shape);
    std::optional<Entry> nearest;
    for (int i = 0; i < compound.getNumChildShapes(); ++i) {
        const btTransform pose = object.getWorldTransform() * compound.getChildTransform(i);
        auto entry = enterShape(object, *compound.getChildShape(i), pose, from, to);
        if (entry && (!nearest || entry->fraction < nearest->fraction)) {
            nearest = entry;
            nearest->child = i;
        }
    }
    return nearest;
}

std::vector<Hit> castRay(const PhysicsWorld& world, ecs::Vec3 origin, ecs::Vec3 direction,
                         float maxDistance, const QueryFilter& filter, bool nearestOnly) {
    const float length = ecs::length(direction);
    if (!(length > 0) || !std::isfinite(length) || !(maxDistance > 0)) return {};
    const btVector3 from = toBullet(origin);
    const btVector3 to = from + toBullet(direction) * (std::min(maxDistance, 1e6f) / length);
    RayCandidates candidates(from, to);
    world.impl().world.getBroadphase()->rayTest(from, to, candidates);
    std::vector<Hit> hits;
    const float span = (to - from).length();
    for (const btCollisionObject* object : candidates.objects) {
        if (!passes(filter, object)) continue;
        const auto entered = enterFraction(*object, from, to);
        if (!entered) continue;
        const btVector3 point = from.lerp(to, entered->fraction);
        const BodyRecord& record = *recordOf(object);
        const ecs::Entity entity =
            entered->child >= 0 ? record.childEntities[std::size_t(entered->child)] : record.entity;
        hits.push_back(
            {entity, fromBullet(point), fromBullet(entered->normal), entered->fraction * span});
    }
    std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) {
        return a.distance != b.distance ? a.distance < b.distance : a.entity < b.entity;
    });
    if (nearestOnly && hits.size() > 1) hits.resize(1);
    return hits;
}

struct SweepResult final : btCollisionWorld::ClosestConvexResultCallback {
    SweepResult(const btVector3& from, const btVector3& to, const QueryFilter& f)
        : ClosestConvexResultCallback(from, to), filter(f) {}
    const QueryFilter& filter;
    bool needsCollision(btBroadphaseProxy* proxy) const override {
        return passes(filter, static_cast<const btCollisionObject*>(proxy->m_clientObject));
    }
    // A surface the shape touches but moves away from (or along) does not stop it: a capsule
    // standing on a floor can walk.
    btScalar addSingleResult(btCollisionWorld::LocalConvexResult& result,
                             bool normalInWorldSpace) override {
        const btVector3 normal = normalInWorldSpace
                                     ? result.m_hitNormalLocal
                                     : result.m_hitCollisionObject->getWorldTransform().getBasis() *
                                           result.m_hitNormalLocal;
        if (normal.dot(m_convexToWorld - m_convexFromWorld) >= 0) return m_closestHitFraction;
        return ClosestConvexResultCallback::addSingleResult(result, normalInWorldSpace);
    }
};

struct OverlapResult final : btCollisionWorld::ContactResultCallback {
    explicit OverlapResult(const QueryFilter& f) : filter(f) {}
    const QueryFilter& filter;
    const btCollisionObject* probe = nullptr;
    std::set<std::uint64_t> entities;
    bool needsCollision(btBroadphaseProxy* proxy) const override {
        return passes(filter, static_cast<const btCollisionObject*>(proxy->m_clientObject));
    }
    btScalar addSingleResult(btManifoldPoint& point, const btCollisionObjectWrapper* a, int, int,
                             const btCollisionObjectWrapper* b, int, int) override {
        if (point.getDistance() > 0) return 0;
        const btCollisionObject* other =
            a->getCollisionObject() == probe ? b->getCollisionObject() : a->getCollisionObject();
        if (const BodyRecord* record = recordOf(other)) entities.insert(record->entity.bits());
        return 0;
    }
};

// A convex query shape: the primitives only (a hull or mesh needs a mesh to come from).
ShapeData queryShape(const content::Collider& shape) {
    std::string problem;
    const bool convexPrimitive = shape.shape != content::ColliderShape::ConvexHull &&
                                 shape.shape != content::ColliderShape::TriangleMesh;
    if (!convexPrimitive) return {};
    return makeColliderShape(shape, {1, 1, 1}, nullptr, true, problem);
}

}  // namespace

std::optional<Hit> raycast(const PhysicsWorld& world, ecs::Vec3 origin, ecs::Vec3 direction,
                           float maxDistance, const QueryFilter& filter) {
    std::vector<Hit> hits = castRay(world, origin, direction, maxDistance, filter, true);
    if (hits.empty()) return std::nullopt;
    return hits.front();
}

std::vector<Hit> raycastAll(const PhysicsWorld& world, ecs::Vec3 origin, ecs::Vec3 direction,
                            float maxDistance, const QueryFilter& filter) {
    return castRay(world, origin, direction, maxDistance, filter, false);
}

std::optional<Hit> sweep(const PhysicsWorld& world, const content::Collider& shape,
                         ecs::Quat rotation, ecs::Vec3 from, ecs::Vec3 to,
                         const QueryFilter& filter) {
    const ShapeData data = queryShape(shape);
    if (!data.shape) return std::nullopt;
    const btVector3 start = toBullet(from);
    const btVector3 end = toBullet(to);
    SweepResult result(start, end, filter);
    world.impl().world.convexSweepTest(static_cast<const btConvexShape*>(data.shape.get()),
                                       toBullet(from, rotation), toBullet(to, rotation), result);
    if (!result.hasHit()) return std::nullopt;
    const BodyRecord* record = recordOf(result.m_hitCollisionObject);
    return Hit{record ? record->entity : ecs::kNullEntity, fromBullet(result.m_hitPointWorld),
               fromBullet(result.m_hitNormalWorld.normalized()),
               static_cast<float>(result.m_closestHitFraction * (end - start).length())};
}

std::vector<ecs::Entity> overlap(const PhysicsWorld& world, const content::Collider& shape,
                                 ecs::Vec3 position, ecs::Quat rotation,
                                 const QueryFilter& filter) {
    const ShapeData data = queryShape(shape);
    if (!data.shape) return {};
    btCollisionObject probe;
    probe.setCollisionShape(data.shape.get());
    probe.setWorldTransform(toBullet(position, rotation));
    OverlapResult result(filter);
    result.probe = &probe;
    world.impl().world.contactTest(&probe, result);
    std::vector<ecs::Entity> entities;
    for (const auto& record : world.impl().records) {
        if (result.entities.contains(record->entity.bits())) entities.push_back(record->entity);
    }
    return entities;
}

content::Collider sphereOf(float radius) {
    content::Collider collider;
    collider.shape = content::ColliderShape::Sphere;
    collider.radius = radius;
    return collider;
}

}  // namespace candela::physics
