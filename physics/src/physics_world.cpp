#include "candela/physics/physics_world.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "bullet_math.h"
#include "physics_world_impl.h"

namespace candela::physics {
namespace {

// A pair's restitution is the bouncier of the two (a rubber ball bounces off a concrete floor
// as rubber does), its friction the geometric mean (Box2D's rule; Bullet's product makes two
// 0.5 surfaces as slippery as ice at 0.25).
btScalar combinedRestitution(const btCollisionObject* a, const btCollisionObject* b) {
    return std::max(a->getRestitution(), b->getRestitution());
}
btScalar combinedFriction(const btCollisionObject* a, const btCollisionObject* b) {
    return std::sqrt(a->getFriction() * b->getFriction());
}

}  // namespace

PhysicsWorld::Impl::Impl(ecs::Registry& r, PhysicsSettings s) : registry(r), settings(s) {
    gCalculateCombinedRestitutionCallback = &combinedRestitution;
    gCalculateCombinedFrictionCallback = &combinedFriction;
    world.setGravity(toBullet(settings.gravity));
    // Two friction directions per contact: a stack of ten boxes leaned 2.4 cm in 5 s with one.
    world.getSolverInfo().m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
    world.getSolverInfo().m_splitImpulse = 1;
}

// Bullet's world walks its objects when it goes: they leave it first.
PhysicsWorld::Impl::~Impl() {
    for (auto& record : records)
        world.removeRigidBody(record->body.get());
}

void PhysicsWorld::Impl::step() {
    for (auto& record : records) {
        if (record->type() == content::BodyType::Dynamic) {
            record->previous = record->body->getWorldTransform();
        }
    }
    const auto h = static_cast<btScalar>(settings.stepSeconds);
    moveCharacters(h);
    const auto start = std::chrono::steady_clock::now();
    world.stepSimulation(h, 0, h);  // no substeps: exactly one step of h
    timings.simulate +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ++timings.steps;
    ++steps;
    for (auto& record : records) {
        if (record->type() == content::BodyType::Dynamic) {
            record->current = record->body->getWorldTransform();
        }
    }
    observeContacts();
    observeTriggers();
}

void PhysicsWorld::Impl::beginEvents() {
    timings = {};
    updateStart = std::chrono::steady_clock::now();
    events.contacts.clear();
    events.triggers.clear();
    contacts.beginUpdate();
    triggers.beginUpdate();
}

void PhysicsWorld::Impl::endEvents() {
    contacts.emitContacts(events.contacts);
    triggers.emitTriggers(events.triggers);
    // The same events as the registry's resource, for systems that declare what they read.
    if (auto* shared = registry.resources().tryGet<PhysicsEvents>()) *shared = events;
    const double total =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - updateStart).count();
    timings.integration = total - timings.simulate;
}

PhysicsWorld::PhysicsWorld(ecs::Registry& registry, PhysicsSettings settings)
    : impl_(std::make_unique<Impl>(registry, settings)) {
    impl_->self = this;
    registry.resources().emplace<PhysicsEvents>();
    setSettings(settings);
}

PhysicsWorld::~PhysicsWorld() {
    impl_->registry.resources().remove<PhysicsEvents>();
}

const PhysicsSettings& PhysicsWorld::settings() const {
    return impl_->settings;
}

void PhysicsWorld::setSettings(const PhysicsSettings& settings) {
    Impl& w = *impl_;
    w.settings = settings;
    if (!(settings.stepSeconds > 0) || !std::isfinite(settings.stepSeconds)) {
        w.diagnostics.error("physics", "settings",
                            "stepSeconds must be positive and finite; using 1/60 s");
        w.settings.stepSeconds = 1.0 / 60.0;
    }
    if (!std::isfinite(settings.gravity.x) || !std::isfinite(settings.gravity.y) ||
        !std::isfinite(settings.gravity.z)) {
        w.diagnostics.error("physics", "settings", "gravity must be finite; using 0, -9.81, 0");
        w.settings.gravity = {0.0f, -9.81f, 0.0f};
    }
    w.settings.maxStepsPerUpdate = std::max<std::uint32_t>(1, w.settings.maxStepsPerUpdate);
    w.settings.solverIterations = std::clamp(w.settings.solverIterations, 1, 1000);
    if (!(w.settings.splitImpulseDepth >= 0) || !std::isfinite(w.settings.splitImpulseDepth)) {
        w.settings.splitImpulseDepth = PhysicsSettings{}.splitImpulseDepth;
    }
    w.world.setGravity(toBullet(w.settings.gravity));
    btContactSolverInfo& solver = w.world.getSolverInfo();
    solver.m_numIterations = w.settings.solverIterations;
    // Bullet compares the signed distance (negative: penetrating) with it.
    solver.m_splitImpulsePenetrationThreshold = -w.settings.splitImpulseDepth;
    for (auto& record : w.records)
        w.applyGravity(*record);
}

void PhysicsWorld::update(double deltaSeconds) {
    Impl& w = *impl_;
    w.beginEvents();
    if (!(deltaSeconds >= 0) || !std::isfinite(deltaSeconds)) {
        w.diagnostics.error("physics", "update",
                            "deltaSeconds must be finite and not negative; no time passes");
        deltaSeconds = 0;
    }
    w.sync();
    const double h = w.settings.stepSeconds;
    w.leftover += deltaSeconds;
    std::uint32_t taken = 0;
    while (w.leftover >= h && taken < w.settings.maxStepsPerUpdate) {
        w.step();
        w.leftover -= h;
        ++taken;
    }
    // Past the step limit the backlog is dropped: the game slows down instead of stalling.
    if (w.leftover >= h) w.leftover = std::fmod(w.leftover, h);
    w.writeBack(w.settings.interpolate ? static_cast<float>(w.leftover / h) : 1.0f);
    w.endEvents();
}

void PhysicsWorld::step() {
    Impl& w = *impl_;
    w.beginEvents();
    w.sync();
    w.step();
    w.writeBack(1.0f);
    w.endEvents();
}

void PhysicsWorld::sync() {
    impl_->sync();
}

const PhysicsEvents& PhysicsWorld::events() const {
    return impl_->events;
}

content::Diagnostics& PhysicsWorld::diagnostics() {
    return impl_->diagnostics;
}

std::optional<BodyState> PhysicsWorld::bodyState(ecs::Entity entity) const {
    const auto found = impl_->byEntity.find(entity.bits());
    if (found == impl_->byEntity.end()) return std::nullopt;
    const btRigidBody& body = *found->second->body;
    return BodyState{fromBullet(body.getWorldTransform().getOrigin()),
                     fromBullet(body.getWorldTransform().getRotation()),
                     fromBullet(body.getLinearVelocity()), fromBullet(body.getAngularVelocity())};
}

PhysicsCounts PhysicsWorld::counts() const {
    PhysicsCounts counts;
    counts.bodies = static_cast<std::uint32_t>(impl_->world.getNumCollisionObjects());
    counts.shapes = static_cast<std::uint32_t>(impl_->records.size());
    for (const auto& record : impl_->records) {
        if (record->type() == content::BodyType::Dynamic && record->body->isActive()) {
            ++counts.activeBodies;
        }
    }
    counts.steps = impl_->steps;
    return counts;
}

PhysicsTimings PhysicsWorld::lastTimings() const {
    return impl_->timings;
}

double PhysicsWorld::leftoverSeconds() const {
    return impl_->leftover;
}

}  // namespace candela::physics
