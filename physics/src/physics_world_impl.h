#pragma once
// PhysicsWorld's Bullet side, shared by the world's files and the queries.
#include <btBulletDynamicsCommon.h>

#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <unordered_map>
#include <utility>
#include <vector>

#include "candela/content/components/collider.h"
#include "candela/content/components/rigid_body.h"
#include "candela/content/diagnostics.h"
#include "candela/physics/physics_world.h"
#include "collider_shapes.h"
#include "contact_tracking.h"
#include "world_pose.h"

namespace candela::physics {

// A Collider on an entity without a RigidBody, below an ancestor that has one: a piece of
// that ancestor's body (a compound shape).
struct BodyPart {
    ecs::Entity entity;
    content::Collider collider;
    WorldPose relative;  // to the body's entity (poseRelativeTo)
    const content::Mesh* mesh = nullptr;

    bool operator==(const BodyPart& o) const {
        return entity == o.entity && collider == o.collider && mesh == o.mesh &&
               relative.position == o.relative.position &&
               relative.rotation == o.relative.rotation && relative.scale == o.relative.scale;
    }
};

// One entity's Bullet object and what it was made from. The collision object's user pointer
// points here, so a hit names its entity.
struct BodyRecord {
    ecs::Entity entity;
    ShapeData shape;
    std::unique_ptr<btRigidBody> body;
    // What the body was made from; a change to any of them makes it again. `collider` is the
    // entity's own, or (a body of parts alone) its first part's, for the layer and trigger.
    content::Collider collider;
    bool ownCollider = true;
    std::vector<BodyPart> parts;
    // Per child of a compound shape, the entity whose collider it is.
    std::vector<ecs::Entity> childEntities;
    std::optional<content::RigidBody> rigidBody;  // the settings part (velocities ignored)
    ecs::Vec3 scale{1, 1, 1};
    const content::Mesh* mesh = nullptr;
    // The pose physics last put on the entity, and the velocities it last wrote: the entity
    // differing from them means game code moved it or set a velocity.
    WorldPose placed;
    ecs::Vec3 writtenPosition{};
    ecs::Quat writtenRotation{};
    ecs::Vec3 writtenLinearVelocity{};
    ecs::Vec3 writtenAngularVelocity{};
    bool written = false;
    // The pose at the start and end of the last step (interpolation).
    btTransform previous = btTransform::getIdentity();
    btTransform current = btTransform::getIdentity();

    content::BodyType type() const {
        return rigidBody ? rigidBody->type : content::BodyType::Static;
    }
    bool trigger() const { return collider.trigger; }
};

inline BodyRecord* recordOf(const btCollisionObject* object) {
    return object ? static_cast<BodyRecord*>(object->getUserPointer()) : nullptr;
}

struct PhysicsWorld::Impl {
    explicit Impl(ecs::Registry& r, PhysicsSettings s);
    ~Impl();

    ecs::Registry& registry;
    const PhysicsWorld* self = nullptr;  // what the queries take
    PhysicsSettings settings;
    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher{&configuration};
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};

    // Records in creation order (what keeps stepping deterministic), found by entity.
    std::vector<std::unique_ptr<BodyRecord>> records;
    std::unordered_map<std::uint64_t, BodyRecord*> byEntity;

    ContactTracker contacts;
    ContactTracker triggers;
    PhysicsEvents events;
    content::Diagnostics diagnostics;
    std::set<std::pair<std::uint64_t, std::string>> reported;  // (entity, message) said once
    double leftover = 0.0;
    PhysicsTimings timings;
    std::chrono::steady_clock::time_point updateStart;
    std::uint64_t steps = 0;

    void sync();  // body_sync.cpp
    void step();
    void writeBack(float alpha);  // body_write_back.cpp
    void beginEvents();
    void endEvents();
    void observeContacts();  // contact_observation.cpp
    void observeTriggers();
    void applyGravity(BodyRecord& record);
    void moveCharacters(float h);  // character_motion.cpp

    // Says a problem once per entity and message, naming the entity.
    void report(ecs::Entity entity, const std::string& message, bool error);
    void destroy(BodyRecord& record);
    void removeStale(const std::set<std::uint64_t>& bodies);
    void syncEntity(ecs::Entity entity, const content::Collider* own, std::vector<BodyPart> parts);
    std::unique_ptr<BodyRecord> make(ecs::Entity entity, const content::Collider* own,
                                     std::vector<BodyPart> parts,
                                     const content::RigidBody* rigidBody, const WorldPose& pose);
    ShapeData makeShape(BodyRecord& record, const content::Collider* own, const WorldPose& pose);
    ecs::Entity bodyOwnerOf(ecs::Entity entity) const;
    void applyGameWrites(BodyRecord& record, const content::RigidBody* rigidBody,
                         const WorldPose& pose);
};

}  // namespace candela::physics
