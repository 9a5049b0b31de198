// The physics benchmark's scene in plain Bullet, for scripts/bench-physics-vs-bullet: the
// same boxes, floor, solver settings and 60 Hz steps as candela-bench-physics, with what a
// game without Candela does each step besides stepping (reading every body's transform, as
// for drawing). Built outside the engine, against Debian's Bullet only.
//   plain_bullet_boxes BODIES [STEPS]
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

// The pair rules physics_world.cpp installs: the larger restitution, the geometric mean of
// the frictions.
btScalar maxRestitution(const btCollisionObject* a, const btCollisionObject* b) {
    return std::max(a->getRestitution(), b->getRestitution());
}
btScalar meanFriction(const btCollisionObject* a, const btCollisionObject* b) {
    return std::sqrt(a->getFriction() * b->getFriction());
}

int main(int argc, char** argv) {
    gCalculateCombinedRestitutionCallback = &maxRestitution;
    gCalculateCombinedFrictionCallback = &meanFriction;
    const int bodies = argc > 1 ? std::max(1, std::atoi(argv[1])) : 1000;
    const int steps = argc > 2 ? std::max(2, std::atoi(argv[2])) : 120;
    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher(&configuration);
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
    world.setGravity(btVector3(0, -9.81f, 0));
    btContactSolverInfo& info = world.getSolverInfo();  // as physics_world.cpp sets it
    info.m_splitImpulse = 1;
    info.m_splitImpulsePenetrationThreshold = -0.005f;
    info.m_numIterations = 50;
    info.m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;

    btBoxShape floorShape(btVector3(50, 0.5f, 50));
    floorShape.setMargin(0.04f);
    btRigidBody floor(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &floorShape));
    floor.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(0, -0.5f, 0)));
    floor.setFriction(0.5f);
    world.addRigidBody(&floor);

    btBoxShape boxShape(btVector3(0.5f, 0.5f, 0.5f));
    boxShape.setMargin(0.04f);
    btVector3 inertia;
    boxShape.calculateLocalInertia(1, inertia);
    std::vector<std::unique_ptr<btRigidBody>> boxes;
    const int columns = std::max(1, int(std::ceil(std::sqrt(bodies / 10.0))));
    for (int i = 0; i < bodies; ++i) {
        const int layer = i / (columns * columns), cell = i % (columns * columns);
        btRigidBody::btRigidBodyConstructionInfo c(1, nullptr, &boxShape, inertia);
        c.m_startWorldTransform.setIdentity();
        c.m_startWorldTransform.setOrigin(btVector3(1.1f * float(cell % columns - columns / 2),
                                                    0.5f + 1.1f * float(layer),
                                                    1.1f * float(cell / columns - columns / 2)));
        c.m_friction = 0.5f;
        c.m_angularDamping = 0.05f;
        boxes.push_back(std::make_unique<btRigidBody>(c));
        world.addRigidBody(boxes.back().get());
    }
    std::vector<float> poses(std::size_t(bodies) * 7);
    std::vector<double> times;
    for (int s = 0; s < steps; ++s) {
        const auto start = std::chrono::steady_clock::now();
        world.stepSimulation(1.0f / 60.0f, 0, 1.0f / 60.0f);
        for (int i = 0; i < bodies; ++i) {
            const btTransform& t = boxes[std::size_t(i)]->getWorldTransform();
            const btQuaternion q = t.getRotation();
            float* out = &poses[std::size_t(i) * 7];
            out[0] = t.getOrigin().x(), out[1] = t.getOrigin().y(), out[2] = t.getOrigin().z();
            out[3] = q.x(), out[4] = q.y(), out[5] = q.z(), out[6] = q.w();
        }
        times.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
    }
    for (auto& b : boxes)
        world.removeRigidBody(b.get());
    world.removeRigidBody(&floor);
    times.erase(times.begin());
    std::sort(times.begin(), times.end());
    std::printf("| %d | %.3f | checksum %.3f |\n", bodies, times[times.size() / 2],
                double(poses[1]));
}
