// Bodies made, remade, moved and destroyed to match the registry's Collider and RigidBody
// components (PhysicsWorld::sync).
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "bullet_math.h"
#include "candela/content/component_validation.h"
#include "candela/content/components/mesh_instance.h"
#include "candela/content/components/name.h"
#include "candela/ecs/hierarchy.h"
#include "candela/ecs/transform.h"
#include "physics_world_impl.h"

namespace candela::physics {
namespace {

using content::BodyType;

bool finitePose(const WorldPose& pose) {
    const float values[] = {pose.position.x, pose.position.y, pose.position.z, pose.rotation.x,
                            pose.rotation.y, pose.rotation.z, pose.rotation.w, pose.scale.x,
                            pose.scale.y,    pose.scale.z};
    return std::all_of(std::begin(values), std::end(values),
                       [](float v) { return std::isfinite(v); });
}

// The settings a body is made from: velocities and `sleeping` change every step.
content::RigidBody settingsOf(content::RigidBody body) {
    body.linearVelocity = {};
    body.angularVelocity = {};
    body.sleeping = false;
    return body;
}

bool sameSettings(const std::optional<content::RigidBody>& a,
                  const std::optional<content::RigidBody>& b) {
    if (a.has_value() != b.has_value()) return false;
    return !a || settingsOf(*a) == settingsOf(*b);
}

bool sameScale(ecs::Vec3 a, ecs::Vec3 b) {
    const auto close = [](float x, float y) {
        return std::fabs(x - y) <= 1e-6f * std::max(std::fabs(x), std::fabs(y));
    };
    return close(a.x, b.x) && close(a.y, b.y) && close(a.z, b.z);
}

const content::Mesh* meshOf(const ecs::Registry& registry, ecs::Entity entity) {
    const auto* instance = registry.tryGet<content::MeshInstance>(entity);
    if (!instance || !instance->model || instance->mesh < 0 ||
        instance->mesh >= static_cast<std::int32_t>(instance->model->meshes.size())) {
        return nullptr;
    }
    return &instance->model->meshes[static_cast<std::size_t>(instance->mesh)];
}

int filterBits(std::uint32_t bits) {
    return static_cast<int>(bits);
}

}  // namespace

void PhysicsWorld::Impl::report(ecs::Entity entity, const std::string& message, bool error) {
    if (!reported.emplace(entity.bits(), message).second) return;
    const auto* name = registry.valid(entity) ? registry.tryGet<content::Name>(entity) : nullptr;
    std::string label = "entity " + std::to_string(entity.index());
    if (name && !name->value.empty()) label += " \"" + name->value + "\"";
    if (error) {
        diagnostics.error("physics", label, message);
    } else {
        diagnostics.warning("physics", label, message);
    }
}

void PhysicsWorld::Impl::destroy(BodyRecord& record) {
    world.removeRigidBody(record.body.get());
    byEntity.erase(record.entity.bits());
}

void PhysicsWorld::Impl::removeStale(const std::set<std::uint64_t>& bodies) {
    const auto stale = [&](const std::unique_ptr<BodyRecord>& record) {
        const bool gone = !bodies.contains(record->entity.bits());
        if (gone) destroy(*record);
        return gone;
    };
    records.erase(std::remove_if(records.begin(), records.end(), stale), records.end());
}

ecs::Entity PhysicsWorld::Impl::bodyOwnerOf(ecs::Entity entity) const {
    for (ecs::Entity up = ecs::parentOf(registry, entity); !up.isNull();
         up = ecs::parentOf(registry, up)) {
        if (registry.has<content::RigidBody>(up)) return up;
    }
    return ecs::kNullEntity;
}

// Every Collider is a body of its own, or a part of the body of its nearest ancestor with a
// RigidBody (when it has none itself); a RigidBody without a Collider is a body of its parts.
void PhysicsWorld::Impl::sync() {
    std::vector<ecs::Entity> roots;
    std::map<std::uint64_t, std::vector<BodyPart>> parts;  // by owner, in view order
    registry.view<const content::Collider>().each([&](ecs::Entity entity,
                                                      const content::Collider& collider) {
        const ecs::Entity owner =
            registry.has<content::RigidBody>(entity) ? ecs::kNullEntity : bodyOwnerOf(entity);
        if (owner.isNull()) {
            roots.push_back(entity);
            return;
        }
        const std::optional<WorldPose> relative = poseRelativeTo(registry, entity, owner);
        if (!relative || !finitePose(*relative)) {
            report(entity,
                   "transform: a collider part needs finite LocalTransforms up to "
                   "its body; left out",
                   true);
            return;
        }
        content::Collider checked = collider;
        bool rejected = false;
        for (const content::ValueProblem& p : content::validateCollider(checked)) {
            report(entity, "collider." + p.field + ": " + p.message, !p.clamped);
            rejected = rejected || !p.clamped;
        }
        if (!rejected) {
            parts[owner.bits()].push_back({entity, checked, *relative, meshOf(registry, entity)});
        }
    });
    for (const auto& [owner, list] : parts) {
        if (!registry.has<content::Collider>(ecs::Entity::fromBits(owner))) {
            roots.push_back(ecs::Entity::fromBits(owner));
        }
    }
    std::set<std::uint64_t> bodies;
    for (const ecs::Entity root : roots)
        bodies.insert(root.bits());
    removeStale(bodies);
    for (const ecs::Entity root : roots) {
        auto found = parts.find(root.bits());
        syncEntity(root, registry.tryGet<content::Collider>(root),
                   found == parts.end() ? std::vector<BodyPart>{} : std::move(found->second));
    }
}

void PhysicsWorld::Impl::syncEntity(ecs::Entity entity, const content::Collider* own,
                                    std::vector<BodyPart> parts) {
    const auto found = byEntity.find(entity.bits());
    BodyRecord* existing = found == byEntity.end() ? nullptr : found->second;
    const auto drop = [&] {
        if (!existing) return;
        destroy(*existing);
        std::erase_if(records, [&](const auto& r) { return r.get() == existing; });
    };
    const std::optional<WorldPose> pose = worldPoseOf(registry, entity);
    if (!pose) {
        report(entity, "transform: a collider needs a LocalTransform; no body", true);
        drop();
        return;
    }
    if (!finitePose(*pose)) {
        // Keep the body where it was: a NaN never reaches Bullet.
        report(entity, "transform: not finite; the body stays where it was", true);
        return;
    }
    std::optional<content::Collider> collider;
    if (own) {
        collider = *own;
        bool rejected = false;
        for (const content::ValueProblem& p : content::validateCollider(*collider)) {
            report(entity, "collider." + p.field + ": " + p.message, !p.clamped);
            rejected = rejected || !p.clamped;
        }
        if (rejected) collider.reset();
    }
    if (!collider && parts.empty()) {
        drop();
        return;
    }
    std::optional<content::RigidBody> body;
    if (const auto* component = registry.tryGet<content::RigidBody>(entity)) {
        body = *component;
        for (const content::ValueProblem& p : content::validateRigidBody(*body)) {
            report(entity, "rigidBody." + p.field + ": " + p.message, false);
        }
    }
    const content::Mesh* mesh = meshOf(registry, entity);
    const content::Collider& flags = collider ? *collider : parts.front().collider;
    if (existing && existing->collider == flags && existing->ownCollider == collider.has_value() &&
        existing->parts == parts && sameSettings(existing->rigidBody, body) &&
        sameScale(existing->scale, pose->scale) && existing->mesh == mesh) {
        applyGameWrites(*existing, body ? &*body : nullptr, *pose);
        return;
    }
    std::unique_ptr<BodyRecord> made = make(entity, collider ? &*collider : nullptr,
                                            std::move(parts), body ? &*body : nullptr, *pose);
    if (!made) {
        drop();
        return;
    }
    byEntity[entity.bits()] = made.get();
    if (existing) {
        // Made again in its old place, so the order bodies step in stays the order they came.
        world.removeRigidBody(existing->body.get());
        const auto at = std::find_if(records.begin(), records.end(),
                                     [&](const auto& r) { return r.get() == existing; });
        *at = std::move(made);
    } else {
        records.push_back(std::move(made));
    }
}

std::unique_ptr<BodyRecord> PhysicsWorld::Impl::make(ecs::Entity entity,
                                                     const content::Collider* own,
                                                     std::vector<BodyPart> parts,
                                                     const content::RigidBody* rigidBody,
                                                     const WorldPose& pose) {
    auto record = std::make_unique<BodyRecord>();
    record->entity = entity;
    record->collider = own ? *own : parts.front().collider;
    record->ownCollider = own != nullptr;
    record->parts = std::move(parts);
    if (rigidBody) record->rigidBody = *rigidBody;
    record->scale = pose.scale;
    record->mesh = meshOf(registry, entity);
    const BodyType type = record->type();
    record->shape = makeShape(*record, own, pose);
    if (!record->shape.shape) return nullptr;
    const content::Collider& collider = record->collider;

    btCollisionShape* shape = record->shape.shape.get();
    const float mass = type == BodyType::Dynamic ? rigidBody->mass : 0.0f;
    btVector3 inertia(0, 0, 0);
    if (mass > 0) shape->calculateLocalInertia(mass, inertia);
    btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, shape, inertia);
    info.m_startWorldTransform = toBullet(pose.position, pose.rotation);
    info.m_friction = rigidBody ? rigidBody->friction : 0.5f;
    info.m_restitution = rigidBody ? rigidBody->restitution : 0.0f;
    info.m_linearDamping = rigidBody ? rigidBody->linearDamping : 0.0f;
    info.m_angularDamping = rigidBody ? rigidBody->angularDamping : 0.0f;
    record->body = std::make_unique<btRigidBody>(info);
    btRigidBody& body = *record->body;
    body.setUserPointer(record.get());

    int flags = body.getCollisionFlags();
    if (type == BodyType::Kinematic) flags |= btCollisionObject::CF_KINEMATIC_OBJECT;
    if (type == BodyType::Static) flags |= btCollisionObject::CF_STATIC_OBJECT;
    if (collider.trigger) flags |= btCollisionObject::CF_NO_CONTACT_RESPONSE;
    body.setCollisionFlags(flags);
    if (type == BodyType::Kinematic || (rigidBody && !rigidBody->canSleep)) {
        body.setActivationState(DISABLE_DEACTIVATION);
    }
    if (type == BodyType::Dynamic) {
        body.setFlags(body.getFlags() | BT_DISABLE_WORLD_GRAVITY);
        body.setLinearVelocity(toBullet(rigidBody->linearVelocity));
        body.setAngularVelocity(toBullet(rigidBody->angularVelocity));
        if (rigidBody->continuousCollision) {
            // Swept when a step moves the body more than half its size (Bullet's CCD).
            btVector3 centre;
            btScalar radius = 0;
            shape->getBoundingSphere(centre, radius);
            body.setCcdMotionThreshold(0.5f * radius);
            body.setCcdSweptSphereRadius(0.5f * radius);
        }
    }
    world.addRigidBody(&body, filterBits(collider.layer), filterBits(collider.mask));
    applyGravity(*record);
    record->previous = record->current = body.getWorldTransform();
    record->placed = pose;
    return record;
}

// The entity's own collider's shape, or a compound of it and its parts' shapes placed where the
// parts are relative to the entity (its scale applied to their offsets and sizes).
ShapeData PhysicsWorld::Impl::makeShape(BodyRecord& record, const content::Collider* own,
                                        const WorldPose& pose) {
    const bool dynamic = record.type() == BodyType::Dynamic;
    std::string problem;
    if (record.parts.empty()) {
        ShapeData shape = makeColliderShape(*own, pose.scale, record.mesh, dynamic, problem);
        if (!problem.empty()) report(record.entity, "collider." + problem, !shape.shape);
        return shape;
    }
    ShapeData compound;
    auto shape = std::make_unique<btCompoundShape>();
    if (own) {
        ShapeData itself = makeColliderShape(*own, pose.scale, record.mesh, dynamic, problem);
        if (!problem.empty()) report(record.entity, "collider." + problem, !itself.shape);
        if (itself.shape) {
            shape->addChildShape(btTransform::getIdentity(), itself.shape.get());
            record.childEntities.push_back(record.entity);
            compound.children.push_back(std::move(itself));
        }
    }
    const auto times = [](ecs::Vec3 a, ecs::Vec3 b) {
        return ecs::Vec3{a.x * b.x, a.y * b.y, a.z * b.z};
    };
    for (const BodyPart& part : record.parts) {
        problem.clear();
        ShapeData piece = makeColliderShape(part.collider, times(pose.scale, part.relative.scale),
                                            part.mesh, dynamic, problem);
        if (!problem.empty()) report(part.entity, "collider." + problem, !piece.shape);
        if (!piece.shape) continue;
        shape->addChildShape(
            toBullet(times(pose.scale, part.relative.position), part.relative.rotation),
            piece.shape.get());
        record.childEntities.push_back(part.entity);
        compound.children.push_back(std::move(piece));
    }
    if (compound.children.empty()) return {};
    compound.shape = std::move(shape);
    return compound;
}

void PhysicsWorld::Impl::applyGravity(BodyRecord& record) {
    if (record.type() != BodyType::Dynamic) return;
    record.body->setGravity(toBullet(settings.gravity) * record.rigidBody->gravityScale);
}

void PhysicsWorld::Impl::applyGameWrites(BodyRecord& record, const content::RigidBody* rigidBody,
                                         const WorldPose& pose) {
    btRigidBody& body = *record.body;
    const BodyType type = record.type();
    const btTransform target = toBullet(pose.position, pose.rotation);
    if (type != BodyType::Dynamic) {
        if (pose.position == record.placed.position && pose.rotation == record.placed.rotation) {
            return;
        }
        // A kinematic body moves to its target during the next step (Bullet derives its
        // velocity from the move, so it pushes what it meets); a static one is put there.
        body.setWorldTransform(target);
        if (type == BodyType::Static) {
            body.setInterpolationWorldTransform(target);
            world.updateSingleAabb(&body);
        }
        record.placed = pose;
        return;
    }
    if (record.written) {
        const auto* local = registry.tryGet<ecs::LocalTransform>(record.entity);
        if (local && (local->position != record.writtenPosition ||
                      local->rotation != record.writtenRotation)) {
            // Game code moved the body: a teleport, with no interpolation across it.
            body.setWorldTransform(target);
            body.setInterpolationWorldTransform(target);
            body.activate(true);
            record.previous = record.current = target;
            record.placed = pose;
        }
    }
    if (rigidBody &&
        (!record.written || rigidBody->linearVelocity != record.writtenLinearVelocity ||
         rigidBody->angularVelocity != record.writtenAngularVelocity)) {
        body.setLinearVelocity(toBullet(rigidBody->linearVelocity));
        body.setAngularVelocity(toBullet(rigidBody->angularVelocity));
        if (record.written) body.activate(true);
    }
}

}  // namespace candela::physics
