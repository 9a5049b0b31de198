#pragma once
// The physics simulation of one registry: Bullet rigid bodies made, updated and destroyed to
// match the entities that have a Collider (content/components/collider.h) and, optionally, a
// RigidBody (rigid_body.h). Game code never touches Bullet: it edits components, reads the
// PhysicsEvents resource and asks queries (physics_queries.h).
//
//   PhysicsWorld physics(registry);            // one per registry
//   physics.update(frame.deltaSeconds);        // before transform propagation, every frame
//   for (const ContactEvent& c : physics.events().contacts) ...
//
// update() advances by fixed steps (PhysicsSettings::stepSeconds, 1/60 s by default): the
// time left over carries into the next frame, and rendered transforms of dynamic bodies are
// interpolated between the last two steps, so motion is smooth at any frame rate while the
// simulation depends only on the number of steps taken. The same scene, steps and writes give
// the same body states, byte for byte. This header needs no Bullet.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "candela/content/diagnostics.h"
#include "candela/ecs/entity.h"
#include "candela/ecs/registry.h"
#include "candela/ecs/transform_math.h"
#include "candela/physics/physics_events.h"

namespace candela::physics {

struct PhysicsSettings {
    double stepSeconds = 1.0 / 60.0;        // the fixed step; > 0
    ecs::Vec3 gravity{0.0f, -9.81f, 0.0f};  // m/s^2
    // At most this many steps per update(): after a long stall the simulation slows down
    // instead of spending ever longer catching up.
    std::uint32_t maxStepsPerUpdate = 8;
    // Rendered transforms of dynamic bodies lag one step behind the simulation and move
    // smoothly between steps. Off: they show the last step as it is.
    bool interpolate = true;
    // The contact solver's passes per step: more holds stacks stiller and costs more
    // (docs/physics-speed-vs-error.md: a stack of ten boxes leans 4 cm in 5 s at 10, 2 mm at 50).
    int solverIterations = 50;
    // Penetrations deeper than this (metres) are pushed out by a separate position pass (split
    // impulse) instead of extra velocity, which would add to a bounce; shallower, resting
    // contacts keep the velocity term that holds stacks still. Bullet's own default is 0.04.
    float splitImpulseDepth = 0.005f;
};

// A body's simulated pose and velocity after the last step (what interpolation started from).
struct BodyState {
    ecs::Vec3 position{};
    ecs::Quat rotation{};
    ecs::Vec3 linearVelocity{};
    ecs::Vec3 angularVelocity{};
};

// What the physics world holds, for tests, leak checks and --stats.
struct PhysicsCounts {
    std::uint32_t bodies = 0;        // Bullet collision objects (bodies, static and trigger)
    std::uint32_t shapes = 0;        // Bullet collision shapes alive
    std::uint32_t activeBodies = 0;  // dynamic bodies awake
    std::uint64_t steps = 0;         // fixed steps taken since the world was made
};

// Where the last update()'s time went, in seconds (steady clock): Bullet's own steps, and what
// the ECS integration adds (bodies synced from components, poses and velocities written back,
// events and character moves).
struct PhysicsTimings {
    double simulate = 0;
    double integration = 0;
    std::uint32_t steps = 0;  // fixed steps the update took
};

class PhysicsWorld {
public:
    explicit PhysicsWorld(ecs::Registry& registry, PhysicsSettings settings = {});
    ~PhysicsWorld();
    PhysicsWorld(const PhysicsWorld&) = delete;
    PhysicsWorld& operator=(const PhysicsWorld&) = delete;

    const PhysicsSettings& settings() const;
    void setSettings(const PhysicsSettings& settings);

    // Makes, rebuilds and destroys bodies to match the registry's components, then takes as
    // many fixed steps as the accumulated time allows and writes dynamic bodies' transforms
    // and velocities back. Problems (a negative mass, a NaN velocity, a degenerate collider)
    // go to `diagnostics` once per entity and field, naming both; the body is clamped or
    // skipped, never simulated with a NaN.
    void update(double deltaSeconds);
    // Takes exactly one fixed step (tests, tools).
    void step();
    // Brings the bodies in line with the registry without stepping (after a scene loads).
    void sync();

    // The events of the last update(): contacts and trigger overlaps that began, stayed or
    // ended during its steps. The registry holds a copy as a resource while this world lives
    // (registry.resources().get<PhysicsEvents>()), for systems that declare
    // readsResource<PhysicsEvents>().
    const PhysicsEvents& events() const;
    // Problems found while syncing bodies; the caller prints or forwards them.
    content::Diagnostics& diagnostics();

    std::optional<BodyState> bodyState(ecs::Entity entity) const;
    PhysicsCounts counts() const;
    PhysicsTimings lastTimings() const;
    // Seconds of simulated time not yet stepped (0 <= leftover < stepSeconds).
    double leftoverSeconds() const;

    // The Bullet world, for the queries in this module (physics_queries.cpp).
    struct Impl;
    Impl& impl() const { return *impl_; }

private:
    std::unique_ptr<Impl> impl_;
};

}  // namespace candela::physics
