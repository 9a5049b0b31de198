#include "candela/physics/physics_debug_lines.h"

#include <LinearMath/btIDebugDraw.h>

#include "bullet_math.h"
#include "physics_world_impl.h"

namespace candela::physics {
namespace {

// Bullet's own drawing of shapes and contacts, collected as segments of one kind at a time.
class LineCollector final : public btIDebugDraw {
public:
    explicit LineCollector(std::vector<DebugLine>& out) : out_(out) {}
    DebugLineKind kind = DebugLineKind::Collider;

    void drawLine(const btVector3& from, const btVector3& to, const btVector3&) override {
        out_.push_back({fromBullet(from), fromBullet(to), kind});
    }
    void drawContactPoint(const btVector3& point, const btVector3& normal, btScalar, int,
                          const btVector3&) override {
        // A short stroke along the normal and a cross: visible from any side.
        constexpr float kSize = 0.05f;
        const ecs::Vec3 p = fromBullet(point);
        out_.push_back({p, fromBullet(point + normal * 4 * kSize), DebugLineKind::Contact});
        out_.push_back(
            {p - ecs::Vec3{kSize, 0, 0}, p + ecs::Vec3{kSize, 0, 0}, DebugLineKind::Contact});
        out_.push_back(
            {p - ecs::Vec3{0, 0, kSize}, p + ecs::Vec3{0, 0, kSize}, DebugLineKind::Contact});
    }
    void reportErrorWarning(const char*) override {}
    void draw3dText(const btVector3&, const char*) override {}
    void setDebugMode(int mode) override { mode_ = mode; }
    int getDebugMode() const override { return mode_; }

private:
    std::vector<DebugLine>& out_;
    int mode_ = DBG_DrawWireframe;
};

}  // namespace

void debugLines(const PhysicsWorld& world, std::vector<DebugLine>& out) {
    out.clear();
    PhysicsWorld::Impl& w = world.impl();
    LineCollector lines(out);
    w.world.setDebugDrawer(&lines);  // what debugDrawObject draws through, for this call only
    for (const auto& record : w.records) {
        lines.kind = record->trigger() ? DebugLineKind::Trigger : DebugLineKind::Collider;
        w.world.debugDrawObject(record->body->getWorldTransform(),
                                record->body->getCollisionShape(), btVector3(1, 1, 1));
    }
    w.world.setDebugDrawer(nullptr);
    const int manifolds = w.dispatcher.getNumManifolds();
    for (int i = 0; i < manifolds; ++i) {
        const btPersistentManifold& manifold = *w.dispatcher.getManifoldByIndexInternal(i);
        for (int p = 0; p < manifold.getNumContacts(); ++p) {
            const btManifoldPoint& point = manifold.getContactPoint(p);
            if (point.getDistance() > 0.005f) continue;
            lines.drawContactPoint(point.getPositionWorldOnB(), point.m_normalWorldOnB,
                                   point.getDistance(), 0, btVector3(1, 0, 0));
        }
    }
}

}  // namespace candela::physics
