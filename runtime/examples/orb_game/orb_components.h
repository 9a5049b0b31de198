#pragma once
// The orb game's state, all of it in components: the ECS holds the game, systems change it.
#include <cstdint>
#include <string>
#include <vector>

#include "candela/ecs/entity.h"
#include "candela/ecs/transform_math.h"

namespace orb {

// The glowing orb the player steers (a sphere light with an emissive sphere): a floating
// physics body whose velocity the steering turns, bouncing off walls (restitution 0.5).
struct Orb {
    float acceleration = 14.0f;  // m/s^2 while a direction key is held
    float maxSpeed = 5.0f;       // m/s
    float radius = 0.3f;         // m, its sphere collider
    candela::ecs::Vec3 start{};  // where a restart puts it
};

// A small light to collect: a trigger sphere the orb flies through.
struct Pickup {
    std::int32_t points = 10;
    bool collected = false;
    candela::ecs::Vec3 home{};
    float lumens = 150.0f;  // restored on restart (collected pickups go dark)
};

// A red sentinel patrolling between two points, a trigger sphere; touching it loses the game.
struct Hazard {
    candela::ecs::Vec3 from{}, to{};
    float speed = 1.0f;  // m/s along the patrol
    float radius = 0.3f;
};

// An entity whose AudioSource the game plays when `plays` happens ("collect": a spark is
// taken; "hit": the orb bumps into a wall or a sentinel catches it). The level places them
// (children of the orb, so the sound comes from where it is).
struct SoundCue {
    std::string plays;
};

// Title: the title menu is up and the clock waits (orb_ui.h).
enum class Status : std::uint8_t { Playing, Won, Lost, Title };

// One per level (on the "rules" entity).
struct GameState {
    float timeLimitSeconds = 40.0f;
    double elapsedSeconds = 0.0;
    std::int32_t score = 0;
    std::int32_t collected = 0;
    std::int32_t total = 0;
    std::int32_t restarts = 0;
    Status status = Status::Playing;
    std::string reason;  // why the game ended ("all sparks collected", "caught", "out of time")
};

// An animated glTF character watching the game (--mascot MODEL.glb, e.g. the shared Fox): it
// idles on its first clip, crossfades to a cheer clip when the player scores (and back to idle
// cheerSeconds later), stays cheering on a win, and crossfades to a sulk clip on a loss.
struct Mascot {
    candela::ecs::Entity player = candela::ecs::kNullEntity;  // holds the AnimationPlayer
    std::int32_t idleClip = 0, cheerClip = 0, sulkClip = 0;
    float fadeSeconds = 0.25f;
    float cheerSeconds = 1.0f;
    std::int32_t lastScore = 0;
    Status lastStatus = Status::Playing;
    double cheerUntil = -1.0;  // scene seconds; < 0: not cheering for a score
    // One row per frame, after the frame's sampling and the mascot's reaction (--state).
    struct Row {
        std::uint32_t frame = 0;
        std::int32_t clip = -1;
        float time = 0;
        std::int32_t nextClip = -1;
        float fadeWeight = 0;
        std::int32_t score = 0;
        Status status = Status::Playing;
    };
    std::vector<Row> log;
};

const char* statusName(Status status);

}  // namespace orb
