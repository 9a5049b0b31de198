// Dynamic bodies' poses and velocities written back to their entities after the steps.
#include "bullet_math.h"
#include "candela/ecs/transform.h"
#include "physics_world_impl.h"

namespace candela::physics {

void PhysicsWorld::Impl::writeBack(float alpha) {
    for (auto& owned : records) {
        BodyRecord& record = *owned;
        if (record.type() != content::BodyType::Dynamic) continue;
        const btRigidBody& body = *record.body;
        // Between the last two steps (the rendered pose lags the simulation by up to a step).
        const btVector3 origin =
            record.previous.getOrigin().lerp(record.current.getOrigin(), alpha);
        const btQuaternion rotation =
            record.previous.getRotation().slerp(record.current.getRotation(), alpha);
        ecs::Vec3 position;
        ecs::Quat orientation;
        worldToLocal(registry, record.entity, fromBullet(origin), fromBullet(rotation), position,
                     orientation);
        auto* local = registry.tryGet<ecs::LocalTransform>(record.entity);
        if (!local) {
            local = &registry.emplace<ecs::LocalTransform>(
                record.entity, ecs::LocalTransform{position, orientation, record.scale});
            registry.markChanged<ecs::LocalTransform>(record.entity);
        } else if (local->position != position || local->rotation != orientation) {
            registry.patch<ecs::LocalTransform>(record.entity, [&](ecs::LocalTransform& t) {
                t.position = position;
                t.rotation = orientation;
            });
        }
        record.writtenPosition = position;
        record.writtenRotation = orientation;

        const ecs::Vec3 linear = fromBullet(body.getLinearVelocity());
        const ecs::Vec3 angular = fromBullet(body.getAngularVelocity());
        const bool sleeping = !body.isActive();
        auto* component = registry.tryGet<content::RigidBody>(record.entity);
        if (component &&
            (component->linearVelocity != linear || component->angularVelocity != angular ||
             component->sleeping != sleeping)) {
            registry.patch<content::RigidBody>(record.entity, [&](content::RigidBody& b) {
                b.linearVelocity = linear;
                b.angularVelocity = angular;
                b.sleeping = sleeping;
            });
        }
        record.writtenLinearVelocity = linear;
        record.writtenAngularVelocity = angular;
        record.written = true;
    }
}

}  // namespace candela::physics
