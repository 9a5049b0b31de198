#include "orb_systems.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "candela/content/components/animation.h"
#include "candela/content/components/audio_source.h"
#include "candela/content/components/light.h"
#include "candela/content/components/rigid_body.h"
#include "candela/ecs/transform.h"
#include "candela/physics/physics_events.h"
#include "orb_components.h"

namespace orb {

namespace {

using candela::content::RigidBody;
using candela::ecs::LocalTransform;
using candela::ecs::Vec3;
using candela::runtime::FrameContext;
using candela::runtime::SceneWorld;

GameState* gameState(SceneWorld& world) {
    GameState* found = nullptr;
    world.registry.view<GameState>().each([&](GameState& s) { found = &s; });
    return found;
}

// Where a sentinel is after `seconds` of patrol: back and forth between its two points.
Vec3 patrolPosition(const Hazard& h, double seconds) {
    const float length = candela::ecs::length(h.to - h.from);
    if (length <= 0.0f) return h.from;
    const double travelled = std::fmod(seconds * h.speed, 2.0 * length);
    const float along = float(travelled <= length ? travelled : 2.0 * length - travelled);
    return h.from + (h.to - h.from) * (along / length);
}

void setLightLumens(SceneWorld& world, candela::ecs::Entity e, float lumens) {
    if (auto* light = world.registry.tryGet<candela::content::Light>(e)) {
        light->lumens = lumens;
        world.registry.markChanged<candela::content::Light>(e);
    }
}

void setOrbColor(SceneWorld& world, std::array<float, 3> color) {
    world.registry.view<const Orb, candela::content::Light>().each(
        [&](candela::ecs::Entity e, const Orb&, candela::content::Light& light) {
            light.color = color;
            world.registry.markChanged<candela::content::Light>(e);
        });
}

constexpr std::array<float, 3> kOrbColor = {1.0f, 0.85f, 0.6f};
// A worn stick rests a little off centre: tilts below this steer nothing.
constexpr float kStickDeadZone = 0.2f;

}  // namespace

candela::runtime::InputActions& addOrbControls(SceneWorld& world) {
    candela::runtime::InputActions actions;
    actions.bindAxis("steer_x", {"key:A", "key:Left", "pad:DpadLeft"},
                     {"key:D", "key:Right", "pad:DpadRight"}, "pad:LeftX", kStickDeadZone);
    // +Z is toward the player (south): W and up steer north.
    actions.bindAxis("steer_z", {"key:W", "key:Up", "pad:DpadUp"},
                     {"key:S", "key:Down", "pad:DpadDown"}, "pad:LeftY", kStickDeadZone);
    actions.bindButton("restart", {"key:R", "pad:Start"});
    return world.registry.resources().emplace<candela::runtime::InputActions>(std::move(actions));
}

namespace {}  // namespace

void restartSystem(SceneWorld& world, const FrameContext& f) {
    const auto* controls = world.registry.resources().tryGet<candela::runtime::InputActions>();
    if (!controls || !controls->pressed("restart", f.keys())) return;
    GameState* state = gameState(world);
    if (!state) return;
    const int32_t restarts = state->restarts + 1;
    *state =
        GameState{state->timeLimitSeconds, 0.0, 0, 0, state->total, restarts, Status::Playing, {}};
    auto& registry = world.registry;
    registry.view<const Orb, LocalTransform, RigidBody>().each(
        [&](candela::ecs::Entity e, const Orb& orb, LocalTransform& local, RigidBody& body) {
            body.linearVelocity = {};
            local.position = orb.start;  // physics takes it as a teleport
            registry.markChanged<LocalTransform>(e);
            registry.markChanged<RigidBody>(e);
        });
    registry.view<Pickup, LocalTransform>().each(
        [&](candela::ecs::Entity e, Pickup& pickup, LocalTransform& local) {
            pickup.collected = false;
            local.position = pickup.home;
            registry.markChanged<LocalTransform>(e);
            setLightLumens(world, e, pickup.lumens);
        });
    setOrbColor(world, kOrbColor);
    std::printf("restart %d\n", restarts);
}

void steerSystem(SceneWorld& world, const FrameContext& f) {
    const GameState* state = gameState(world);
    if (!state || state->status != Status::Playing) return;
    const auto* controls = world.registry.resources().tryGet<candela::runtime::InputActions>();
    if (!controls) return;
    // Keys give -1 / +1, the stick past its dead zone a part of it: full speed along held keys.
    const Vec3 push{controls->axis("steer_x", f.keys()), 0.0f, controls->axis("steer_z", f.keys())};
    const float dt = float(std::min(f.deltaSeconds, 0.1));
    world.registry.view<const Orb, RigidBody>().each(
        [&](candela::ecs::Entity e, const Orb& orb, RigidBody& body) {
            // Arcade steering: the velocity physics left (after any bounce off a wall) turns
            // toward the wanted one (full speed along the held direction, or rest) by at most
            // `acceleration` per second; physics moves the orb and bounces it.
            // Full speed along held keys; a stick part way gives part of it.
            Vec3 wanted{};
            if (float len = candela::ecs::length(push); len > 0.0f) {
                wanted = push * (orb.maxSpeed / std::max(len, 1.0f));
            }
            Vec3 velocity{body.linearVelocity.x, 0.0f, body.linearVelocity.z};
            Vec3 change = wanted - velocity;
            const float maxChange = orb.acceleration * dt;
            if (float len = candela::ecs::length(change); len > maxChange) {
                change *= maxChange / len;
            }
            body.linearVelocity = velocity + change;
            world.registry.markChanged<RigidBody>(e);
        });
}

void patrolSystem(SceneWorld& world, const FrameContext&) {
    const GameState* state = gameState(world);
    if (!state) return;
    world.registry.view<const Hazard, LocalTransform>().each(
        [&](candela::ecs::Entity e, const Hazard& h, LocalTransform& local) {
            local.position = patrolPosition(h, state->elapsedSeconds);
            world.registry.markChanged<LocalTransform>(e);
        });
}

// The orb's trigger overlaps of the last physics update: with sparks (collected) and with
// sentinels (caught).
template <class F>
void eachOrbTouch(SceneWorld& world, F&& touched) {
    // The registry's copy: systems that declare readsResource<PhysicsEvents>() may read it
    // side by side.
    const auto* events = world.registry.resources().tryGet<candela::physics::PhysicsEvents>();
    if (!events) return;
    for (const candela::physics::TriggerEvent& e : events->triggers) {
        if (e.phase != candela::physics::ContactPhase::End && world.registry.valid(e.other) &&
            world.registry.has<Orb>(e.other)) {
            touched(e.trigger);
        }
    }
}

// Starts the sounds the level cued for `event` from their beginning, at `gain`.
void playSound(SceneWorld& world, const std::string& event, float gain = 1.0f) {
    using candela::content::AudioSource;
    world.registry.view<const SoundCue, AudioSource>().each(
        [&](candela::ecs::Entity e, const SoundCue& cue, const AudioSource&) {
            if (cue.plays != event) return;
            world.registry.patch<AudioSource>(e, [&](AudioSource& source) {
                source.gain = gain;
                source.play();
            });
        });
}

void collectSystem(SceneWorld& world, const FrameContext&) {
    GameState* state = gameState(world);
    if (!state || state->status != Status::Playing) return;
    eachOrbTouch(world, [&](candela::ecs::Entity e) {
        Pickup* pickup = world.registry.tryGet<Pickup>(e);
        if (!pickup || pickup->collected) return;
        pickup->collected = true;
        state->score += pickup->points;
        state->collected += 1;
        // Gone dark and out of sight below the floor (kept, so a restart brings it back).
        world.registry.patch<LocalTransform>(e, [&](LocalTransform& local) {
            local.position = pickup->home - Vec3{0.0f, 10.0f, 0.0f};
        });
        setLightLumens(world, e, 0.0f);
        playSound(world, "collect");
    });
}

// The orb bumping into a wall: a thud as loud as the bump. A head-on hit at the top speed gives
// the 1 kg orb m v (1 + restitution) = 7.5 N s; a graze is quieter, a touch silent.
void bumpSystem(SceneWorld& world, const FrameContext&) {
    const auto* events = world.registry.resources().tryGet<candela::physics::PhysicsEvents>();
    if (!events) return;
    float strongest = 0.0f;
    for (const candela::physics::ContactEvent& c : events->contacts) {
        if (c.phase != candela::physics::ContactPhase::Begin) continue;
        const bool orb = (world.registry.valid(c.a) && world.registry.has<Orb>(c.a)) ||
                         (world.registry.valid(c.b) && world.registry.has<Orb>(c.b));
        if (orb) strongest = std::max(strongest, c.impulse);
    }
    if (strongest > 0.3f) playSound(world, "hit", std::min(1.0f, strongest / 7.5f));
}

void refereeSystem(SceneWorld& world, const FrameContext& f) {
    GameState* state = gameState(world);
    if (!state || state->status != Status::Playing) return;
    state->elapsedSeconds += f.deltaSeconds;
    bool caught = false;
    eachOrbTouch(world,
                 [&](candela::ecs::Entity e) { caught = caught || world.registry.has<Hazard>(e); });
    if (state->collected == state->total) {
        state->status = Status::Won;
        state->reason = "all sparks collected";
        setOrbColor(world, {0.2f, 1.0f, 0.3f});
    } else if (caught) {
        state->status = Status::Lost;
        state->reason = "caught by a sentinel";
        setOrbColor(world, {1.0f, 0.1f, 0.05f});
        playSound(world, "hit");
    } else if (state->elapsedSeconds >= state->timeLimitSeconds) {
        state->status = Status::Lost;
        state->reason = "out of time";
        setOrbColor(world, {0.3f, 0.3f, 1.0f});
    }
    if (state->status != Status::Playing) {
        std::printf("%s at frame %u: %s, score %d (%d/%d sparks) after %.2f s\n",
                    statusName(state->status), f.frame, state->reason.c_str(), state->score,
                    state->collected, state->total, state->elapsedSeconds);
    }
}

// Runs after the engine sampled this frame's pose: a reaction starts blending next frame.
void mascotSystem(SceneWorld& world, const FrameContext& f) {
    const GameState* state = gameState(world);
    if (!state) return;
    world.registry.view<Mascot>().each([&](candela::ecs::Entity, Mascot& m) {
        auto* player = world.registry.tryGet<candela::content::AnimationPlayer>(m.player);
        if (!player) return;
        const auto blendTo = [&](std::int32_t clip) {
            const std::int32_t heading = player->nextClip >= 0 ? player->nextClip : player->clip;
            if (heading != clip) player->crossfade(clip, m.fadeSeconds);
        };
        if (state->status != m.lastStatus) {
            m.cheerUntil = -1.0;
            blendTo(state->status == Status::Lost  ? m.sulkClip
                    : state->status == Status::Won ? m.cheerClip
                                                   : m.idleClip);  // a restart
        } else if (state->status == Status::Playing && state->score > m.lastScore) {
            m.cheerUntil = f.seconds + m.cheerSeconds;
            blendTo(m.cheerClip);
        } else if (m.cheerUntil >= 0.0 && f.seconds >= m.cheerUntil) {
            m.cheerUntil = -1.0;
            blendTo(m.idleClip);
        }
        m.lastStatus = state->status;
        m.lastScore = state->score;
        m.log.push_back({f.frame, player->clip, player->time, player->nextClip,
                         player->fadeWeight(), state->score, state->status});
    });
}

void animateSystem(SceneWorld& world, const FrameContext& f) {
    // Sparks bob so they read as alive; by scene time, so headless frames repeat.
    world.registry.view<const Pickup, LocalTransform>().each(
        [&](candela::ecs::Entity e, const Pickup& pickup, LocalTransform& local) {
            if (pickup.collected) return;
            const float phase = pickup.home.x * 1.3f + pickup.home.z * 0.7f;
            local.position.y = pickup.home.y + 0.08f * std::sin(3.0f * float(f.seconds) + phase);
            world.registry.markChanged<LocalTransform>(e);
        });
}

void addOrbSystems(candela::runtime::Application& app) {
    using candela::content::Light;
    using candela::ecs::Phase;
    // Each declares what it touches: the scheduler keeps the order below between systems that
    // share something one of them writes, and runs the rest side by side (animate and hud).
    app.addSystem("restart", Phase::Update, restartSystem)
        .writes<GameState, Orb, Pickup, LocalTransform, Light, RigidBody>();
    app.addSystem("steer", Phase::Update, steerSystem).reads<GameState, Orb>().writes<RigidBody>();
    app.addSystem("patrol", Phase::Update, patrolSystem)
        .reads<GameState, Hazard>()
        .writes<LocalTransform>();
    // Both read the physics events of the last frame (physics runs alone in PostUpdate).
    using candela::content::AudioSource;
    app.addSystem("collect", Phase::Update, collectSystem)
        .reads<Orb, SoundCue>()
        .readsResource<candela::physics::PhysicsEvents>()
        .writes<GameState, Pickup, LocalTransform, Light, AudioSource>();
    app.addSystem("referee", Phase::Update, refereeSystem)
        .reads<Orb, Hazard, SoundCue>()
        .readsResource<candela::physics::PhysicsEvents>()
        .writes<GameState, Light, AudioSource>();
    app.addSystem("bump", Phase::Update, bumpSystem)
        .reads<Orb, SoundCue>()
        .readsResource<candela::physics::PhysicsEvents>()
        .writes<AudioSource>();
    app.addSystem("mascot", Phase::Update, mascotSystem)
        .reads<GameState>()
        .writes<Mascot, candela::content::AnimationPlayer>();
    app.addSystem("animate", Phase::Update, animateSystem).reads<Pickup>().writes<LocalTransform>();
    // The HUD: the window title, rewritten only when what it says changes.
    app.addSystem("hud", Phase::Update,
                  [&app, last = std::string()](SceneWorld& world, const FrameContext&) mutable {
                      const GameState* s = gameState(world);
                      if (!s) return;
                      char title[160];
                      if (s->status == Status::Playing) {
                          std::snprintf(
                              title, sizeof title, "Orb - score %d - sparks %d/%d - %.0f s left",
                              s->score, s->collected, s->total,
                              std::ceil(std::max(0.0, s->timeLimitSeconds - s->elapsedSeconds)));
                      } else {
                          std::snprintf(title, sizeof title,
                                        "Orb - you %s (%s), score %d - press R to restart",
                                        statusName(s->status), s->reason.c_str(), s->score);
                      }
                      if (last != title) {
                          last = title;
                          app.setWindowTitle(title);
                      }
                  })
        .reads<GameState>();
}

}  // namespace orb
