// The application's systems on ecs::Scheduler, without a GPU (Application::update runs one
// frame of systems): disjoint read/write sets share a stage and run at once, conflicting ones
// run in the order added, and transform propagation follows the Update phase.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "candela/content/components/animation.h"
#include "candela/content/components/name.h"
#include "candela/ecs/transform.h"
#include "candela/runtime/application.h"
#include "candela/runtime/scene_source.h"

using namespace candela;
using namespace candela::runtime;

namespace {

struct Position {
    float x = 0.0f;
};
struct Health {
    int points = 0;
};

// Marks `mine` and waits (at most 5 s) for `other`: true when both systems were running at once.
bool meetWithin5s(std::atomic<bool>& mine, const std::atomic<bool>& other) {
    mine = true;
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (!other && std::chrono::steady_clock::now() < until)
        std::this_thread::yield();
    return other;
}

}  // namespace

TEST(ApplicationSystems, DisjointSetsShareAStageAndRunAtOnce) {
    Application app(ApplicationOptions{});
    std::atomic<bool> aRunning = false, bRunning = false;
    std::atomic<int> met = 0;
    app.addSystem(
           "a", ecs::Phase::Update,
           [&](SceneWorld&, const FrameContext&) { met += meetWithin5s(aRunning, bRunning); })
        .writes<Position>();
    app.addSystem(
           "b", ecs::Phase::Update,
           [&](SceneWorld&, const FrameContext&) { met += meetWithin5s(bRunning, aRunning); })
        .writes<Health>();
    const std::string plan = app.describeSystems();
    EXPECT_NE(plan.find("Update: a | b\n"), std::string::npos) << plan;
    if (ecs::JobSystem::defaultWorkerCount() == 0) {
        GTEST_SKIP() << "one hardware thread: the job system has no worker to run b beside a";
    }
    app.update(FrameContext{});
    EXPECT_EQ(met.load(), 2) << "a and b did not run at the same time";
}

TEST(ApplicationSystems, ConflictingSetsRunInTheOrderAdded) {
    Application app(ApplicationOptions{});
    std::mutex mutex;
    std::vector<std::string> order;
    auto record = [&](std::string name) {
        return [&, name](SceneWorld&, const FrameContext&) {
            const std::lock_guard lock(mutex);
            order.push_back(name);
        };
    };
    // Added in an order the scheduler must keep: each conflicts with the one before it.
    app.addSystem("writer", ecs::Phase::Update, record("writer")).writes<Position>();
    app.addSystem("reader", ecs::Phase::Update, record("reader")).reads<Position>();
    app.addSystem("rewriter", ecs::Phase::Update, record("rewriter"))
        .reads<Health>()
        .writes<Position>();
    app.addSystem("anything", record("anything"));  // the exclusive overload: after all of them
    app.addSystem("early", ecs::Phase::PreUpdate, record("early")).writes<Position>();
    const std::string plan = app.describeSystems();
    EXPECT_NE(plan.find("PreUpdate: early\n(sync)\nUpdate: writer\nUpdate: reader\nUpdate: "
                        "rewriter\n(sync)\nUpdate exclusive: anything\n(sync)\n(sync)\n"
                        "PostUpdate exclusive: physics\n(sync)\n"
                        "PostUpdate exclusive: propagate transforms\n"),
              std::string::npos)
        << plan;
    for (int frame = 0; frame < 3; ++frame) {
        order.clear();
        app.update(FrameContext{});
        EXPECT_EQ(order,
                  (std::vector<std::string>{"early", "writer", "reader", "rewriter", "anything"}));
    }
}

TEST(ApplicationSystems, TransformsPropagateAfterUpdateSystems) {
    Application app(ApplicationOptions{});
    ecs::Registry& registry = app.world().registry;
    const ecs::Entity e = registry.create();
    registry.emplace<ecs::LocalTransform>(e);
    registry.emplace<ecs::WorldTransform>(e);
    app.addSystem("move", ecs::Phase::Update,
                  [&](SceneWorld& world, const FrameContext& f) {
                      world.registry.get<ecs::LocalTransform>(e).position.x = float(f.frame + 1);
                      world.registry.markChanged<ecs::LocalTransform>(e);
                  })
        .writes<ecs::LocalTransform>();
    FrameContext frame;
    frame.frame = 2;
    app.update(frame);
    EXPECT_FLOAT_EQ(registry.get<ecs::WorldTransform>(e).position().x, 3.0f);
}

// The demo's fox (issue 20) walks, crossfades to Run after four seconds and moves down the
// hall; driven through the application's scheduler without a GPU, at 30 frames per second.
TEST(ApplicationSystems, DemoFoxWalksThenCrossfadesToRun) {
    std::string error;
    std::optional<LoadedScene> scene = loadScene("builtin:demo", error);
    ASSERT_TRUE(scene) << error;
    Application app(ApplicationOptions{});
    app.setWorld(std::move(scene->world));
    scene->addSystems(app);
    ecs::Registry& registry = app.world().registry;
    content::AnimationPlayer* player = nullptr;
    registry.view<content::AnimationPlayer>().each(
        [&](ecs::Entity, content::AnimationPlayer& p) { player = &p; });
    ASSERT_NE(player, nullptr) << "the demo has no animated fox";
    ecs::Entity foxRoot = ecs::kNullEntity;
    registry.view<content::Name>().each([&](ecs::Entity e, const content::Name& name) {
        if (name.value == "fox" && foxRoot == ecs::kNullEntity) foxRoot = e;  // the placed root
    });
    ASSERT_NE(foxRoot, ecs::kNullEntity);
    const std::int32_t walk = player->findClip("Walk");
    const std::int32_t run = player->findClip("Run");
    const float startZ = registry.get<ecs::LocalTransform>(foxRoot).position.z;
    uint32_t frame = 0;
    auto runUntil = [&](uint32_t lastFrame) {
        for (; frame <= lastFrame; ++frame) {
            FrameContext f;
            f.frame = frame;
            f.seconds = frame / 30.0;
            f.deltaSeconds = frame == 0 ? 0.0 : 1.0 / 30.0;
            f.headless = true;
            app.update(f);
        }
    };
    runUntil(110);  // 3.67 s
    EXPECT_EQ(player->clip, walk);
    EXPECT_EQ(player->nextClip, -1);
    const float walked = registry.get<ecs::LocalTransform>(foxRoot).position.z - startZ;
    EXPECT_NEAR(walked, 0.5f * 110.0f / 30.0f, 0.05f) << "walking at 0.5 m/s";
    runUntil(135);  // 4.5 s: half way through the one-second crossfade
    EXPECT_EQ(player->clip, walk);
    EXPECT_EQ(player->nextClip, run);
    EXPECT_NEAR(player->fadeWeight(), 0.5f, 0.04f);
    runUntil(170);  // 5.67 s
    EXPECT_EQ(player->clip, run);
    EXPECT_EQ(player->nextClip, -1);
}
