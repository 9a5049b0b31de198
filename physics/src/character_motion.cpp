// CharacterController movement at each fixed step: collide and slide with capsule sweeps
// (Fauerby 2003, "Improved Collision detection and Response"), a step up before the walk
// and a step down after it, so ledges up to stepHeight are climbed and the character stays
// on the slopes it can stand on.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "bullet_math.h"
#include "candela/content/component_validation.h"
#include "candela/ecs/transform.h"
#include "candela/physics/character_controller.h"
#include "candela/physics/physics_queries.h"
#include "physics_world_impl.h"

namespace candela::physics {
namespace {

constexpr int kSlideIterations = 4;
constexpr float kGroundProbeInset = 2e-3f;   // metres towards the capsule's axis
constexpr float kGroundProbeHeight = 0.02f;  // metres above the contact

struct Walker {
    const PhysicsWorld& world;
    content::Collider capsule;
    QueryFilter filter;
    float skin;

    // Moves from `at` by `motion`, stopping `skin` short of the first surface; the hit, if
    // any. The sweep reaches `skin` further than the move, so a surface just past the move's
    // end still keeps its gap.
    std::optional<Hit> move(ecs::Vec3& at, ecs::Vec3 motion) const {
        const float length = ecs::length(motion);
        if (!(length > 1e-7f)) return std::nullopt;
        const ecs::Vec3 reach = motion * ((length + skin) / length);
        const std::optional<Hit> hit = sweep(world, capsule, {}, at, at + reach, filter);
        if (!hit || hit->distance - skin >= length) {
            at += motion;
            return std::nullopt;
        }
        at += motion * (std::max(0.0f, hit->distance - skin) / length);
        return hit;
    }

    // Up by at most `height`; how far it went.
    float lift(ecs::Vec3& at, float height) const {
        const float before = at.y;
        move(at, {0, height, 0});
        return at.y - before;
    }

    // Walks by `motion`, sliding along walls; ground too steep to stand on is a wall too.
    void walk(ecs::Vec3& at, ecs::Vec3 motion, float minGroundY) const;

    // Down by at most `depth` onto ground it can stand on: that ground's normal, with `at`
    // on it. Nullopt (and `at` unchanged) when there is none within reach.
    std::optional<ecs::Vec3> land(ecs::Vec3& at, float depth, float minGroundY) const;
};

// The normal of the surface under a sweep's contact point. A capsule's round bottom meets a
// ledge's edge with a normal tilted towards the capsule's centre, which is no ground to stand
// on; a short ray just inside the edge finds the top face the character will stand on.
ecs::Vec3 groundUnder(const Walker& walker, const Hit& hit, ecs::Vec3 centre) {
    ecs::Vec3 inward{centre.x - hit.point.x, 0, centre.z - hit.point.z};
    const float length = ecs::length(inward);
    if (length > 1e-6f) inward = inward * (kGroundProbeInset / length);
    const ecs::Vec3 from = hit.point + inward + ecs::Vec3{0, kGroundProbeHeight, 0};
    const std::optional<Hit> probe =
        raycast(walker.world, from, {0, -1, 0}, 2 * kGroundProbeHeight, walker.filter);
    return probe ? probe->normal : hit.normal;
}

ecs::Vec3 withoutAlong(ecs::Vec3 v, ecs::Vec3 n) {
    return v - n * ecs::dot(v, n);
}

void Walker::walk(ecs::Vec3& at, ecs::Vec3 motion, float minGroundY) const {
    for (int i = 0; i < kSlideIterations; ++i) {
        const ecs::Vec3 start = at;
        const std::optional<Hit> hit = move(at, motion);
        if (!hit) return;
        ecs::Vec3 n = hit->normal;
        if (n.y < minGroundY) {
            n.y = 0;
            const float len = ecs::length(n);
            if (len > 1e-6f) n = n * (1 / len);
        }
        motion = withoutAlong(motion - (at - start), n);
        motion.y = 0;
    }
}

std::optional<ecs::Vec3> Walker::land(ecs::Vec3& at, float depth, float minGroundY) const {
    ecs::Vec3 down = at;
    const std::optional<Hit> hit = move(down, {0, -depth, 0});
    if (!hit) return std::nullopt;
    const ecs::Vec3 normal = groundUnder(*this, *hit, down);
    if (normal.y < minGroundY) return std::nullopt;
    at = down;
    return normal;
}

// Moves by `motion`, sliding along each surface met (its part along the normal removed).
void slide(const Walker& walker, ecs::Vec3& at, ecs::Vec3 motion) {
    for (int i = 0; i < kSlideIterations; ++i) {
        const ecs::Vec3 start = at;
        const std::optional<Hit> hit = walker.move(at, motion);
        if (!hit) return;
        motion = withoutAlong(motion - (at - start), hit->normal);
    }
}

}  // namespace

void PhysicsWorld::Impl::moveCharacters(float h) {
    registry.view<CharacterController, ecs::LocalTransform>().each(
        [&](ecs::Entity entity, CharacterController& c, ecs::LocalTransform& local) {
            if (!std::isfinite(local.position.x) || !std::isfinite(local.position.y) ||
                !std::isfinite(local.position.z)) {
                report(entity, "transform: not finite; the character stays where it was", true);
                return;
            }
            const float radius = std::clamp(c.radius, content::kMinColliderSize, 1e3f);
            const float height = std::max(c.height, 2 * radius);
            Walker walker{*self, {}, {}, std::clamp(c.skinWidth, 1e-4f, radius)};
            walker.capsule.shape = content::ColliderShape::Capsule;
            walker.capsule.radius = radius;
            walker.capsule.height = height;
            walker.filter.layers = c.mask;
            walker.filter.ignore = entity;
            const float minGroundY = std::cos(std::clamp(c.maxSlopeDegrees, 0.0f, 89.0f) *
                                              std::numbers::pi_v<float> / 180);
            const float stepHeight = std::clamp(c.stepHeight, 0.0f, height);

            if (c.grounded && c.jump) {
                c.verticalSpeed = c.jumpSpeed;
                c.grounded = false;
            }
            c.jump = false;
            const ecs::Vec3 walk{c.desiredVelocity.x * h, 0, c.desiredVelocity.z * h};
            ecs::Vec3 at = local.position;
            if (c.grounded) {
                // Over a step first: up by stepHeight, walk, and down onto ground it can
                // stand on. Where that lands nowhere (a ledge too tall, an edge), walk at
                // ground height instead, following the ground down by up to a step.
                ecs::Vec3 stepped = at;
                const float raised = walker.lift(stepped, stepHeight);
                walker.walk(stepped, walk, minGroundY);
                if (auto ground = walker.land(stepped, raised + stepHeight, minGroundY)) {
                    at = stepped;
                    c.groundNormal = *ground;
                } else {
                    walker.walk(at, walk, minGroundY);
                    if (auto flat = walker.land(at, stepHeight, minGroundY)) {
                        c.groundNormal = *flat;
                    } else {
                        c.grounded = false;  // walked off: falls from the next step on
                        c.groundNormal = {0, 1, 0};
                    }
                }
            } else {
                c.verticalSpeed += settings.gravity.y * c.gravityScale * h;
                walker.walk(at, walk, minGroundY);
                const float rise = c.verticalSpeed * h;
                if (rise > 0) {
                    // Rising: a ceiling ends the jump.
                    if (walker.move(at, {0, rise, 0})) c.verticalSpeed = 0;
                } else if (auto ground = walker.land(at, -rise, minGroundY)) {
                    c.grounded = true;
                    c.groundNormal = *ground;
                    c.verticalSpeed = 0;
                } else {
                    // Falling, or on ground too steep to stand on: it slides along what it
                    // meets (down the slope, off an edge) instead of hanging there.
                    slide(walker, at, {0, rise, 0});
                }
            }
            if (at.x != local.position.x || at.y != local.position.y || at.z != local.position.z) {
                local.position = at;
                registry.markChanged<ecs::LocalTransform>(entity);
                // Its kinematic body, if any, is there for this step's contacts and triggers.
                if (auto found = byEntity.find(entity.bits()); found != byEntity.end()) {
                    BodyRecord& record = *found->second;
                    record.body->setWorldTransform(toBullet(at, local.rotation));
                    record.placed.position = at;
                }
            }
        });
}

}  // namespace candela::physics
