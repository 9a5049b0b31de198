// The pairs touching after a step: solid contacts from Bullet's manifolds, trigger overlaps
// from a contact test per trigger (Bullet makes no pairs between two static or kinematic
// objects, and a trigger must see a kinematic character walk into it).
#include <algorithm>

#include "bullet_math.h"
#include "physics_world_impl.h"

namespace candela::physics {
namespace {

// Manifolds keep points a little apart (Bullet's contact breaking threshold); only points
// this close count as touching.
constexpr btScalar kTouchDistance = 0.005f;

struct TriggerOverlaps final : btCollisionWorld::ContactResultCallback {
    const btCollisionObject* trigger = nullptr;
    std::map<BodyPair, Touch>* touching = nullptr;

    btScalar addSingleResult(btManifoldPoint& point, const btCollisionObjectWrapper* a, int, int,
                             const btCollisionObjectWrapper* b, int, int) override {
        if (point.getDistance() > kTouchDistance) return 0;
        const btCollisionObject* other =
            a->getCollisionObject() == trigger ? b->getCollisionObject() : a->getCollisionObject();
        const BodyRecord* self = recordOf(trigger);
        const BodyRecord* record = recordOf(other);
        if (self && record) (*touching)[{self->entity.bits(), record->entity.bits()}] = {};
        return 0;
    }
};

}  // namespace

void PhysicsWorld::Impl::observeContacts() {
    std::map<BodyPair, Touch> touching;
    const int manifolds = dispatcher.getNumManifolds();
    for (int i = 0; i < manifolds; ++i) {
        const btPersistentManifold& manifold = *dispatcher.getManifoldByIndexInternal(i);
        const BodyRecord* a = recordOf(manifold.getBody0());
        const BodyRecord* b = recordOf(manifold.getBody1());
        if (!a || !b || a->trigger() || b->trigger()) continue;
        const btManifoldPoint* deepest = nullptr;
        float impulse = 0.0f;
        for (int p = 0; p < manifold.getNumContacts(); ++p) {
            const btManifoldPoint& point = manifold.getContactPoint(p);
            if (point.getDistance() > kTouchDistance) continue;
            if (!deepest || point.getDistance() < deepest->getDistance()) deepest = &point;
            impulse = std::max(impulse, static_cast<float>(point.getAppliedImpulse()));
        }
        if (!deepest) continue;
        // Bullet's normal points from body 1 to body 0; the event's from b to a.
        const bool swap = b->entity.bits() < a->entity.bits();
        const btVector3 normal = swap ? -deepest->m_normalWorldOnB : deepest->m_normalWorldOnB;
        const btVector3 point =
            0.5f * (deepest->getPositionWorldOnA() + deepest->getPositionWorldOnB());
        const BodyPair pair = swap ? BodyPair{b->entity.bits(), a->entity.bits()}
                                   : BodyPair{a->entity.bits(), b->entity.bits()};
        Touch& touch = touching[pair];
        touch = {fromBullet(point), fromBullet(normal), std::max(touch.impulse, impulse)};
    }
    contacts.observeStep(touching);
}

void PhysicsWorld::Impl::observeTriggers() {
    std::map<BodyPair, Touch> touching;
    for (const auto& record : records) {
        if (!record->trigger()) continue;
        TriggerOverlaps overlaps;
        overlaps.trigger = record->body.get();
        overlaps.touching = &touching;
        overlaps.m_collisionFilterGroup = static_cast<int>(record->collider.layer);
        overlaps.m_collisionFilterMask = static_cast<int>(record->collider.mask);
        world.contactTest(record->body.get(), overlaps);
    }
    triggers.observeStep(touching);
}

}  // namespace candela::physics
