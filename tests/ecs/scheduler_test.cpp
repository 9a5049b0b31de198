#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <candela/ecs/scheduler.h>
#include <candela/ecs/transform_system.h>

#include "test_components.h"

namespace candela::ecs {
namespace {

using test::Health;
using test::Position;
using test::Velocity;

struct Time {
    float delta = 0.5f;
    int frame = 0;
};

// Records the order systems ran in (from any thread).
struct RunLog {
    std::mutex mutex;
    std::vector<std::string> entries;
    void add(std::string name) {
        const std::lock_guard lock(mutex);
        entries.push_back(std::move(name));
    }
    std::size_t position(const std::string& name) {
        const std::lock_guard lock(mutex);
        return static_cast<std::size_t>(std::find(entries.begin(), entries.end(), name) -
                                        entries.begin());
    }
};

TEST(Scheduler, ConflictingSystemsKeepDeclarationOrder) {
    Registry registry;
    JobSystem jobs(2);
    Scheduler scheduler(registry, jobs);
    RunLog log;
    scheduler.addSystem("integrate", Phase::Update, [&](SystemContext&) { log.add("integrate"); })
        .reads<Velocity>()
        .writes<Position>();
    scheduler.addSystem("damage", Phase::Update, [&](SystemContext&) { log.add("damage"); })
        .writes<Health>();
    scheduler.addSystem("report", Phase::Update, [&](SystemContext&) { log.add("report"); })
        .reads<Position, Health>();
    scheduler.addSystem("input", Phase::PreUpdate, [&](SystemContext&) { log.add("input"); })
        .writes<Velocity>();
    EXPECT_EQ(scheduler.describe(),
              "PreUpdate: input\n(sync)\n"
              "Update: integrate | damage\n"
              "Update: report\n(sync)\n");
    for (int frame = 0; frame < 20; ++frame) {
        log.entries.clear();
        scheduler.run();
        ASSERT_EQ(log.entries.size(), 4u);
        EXPECT_EQ(log.entries.front(), "input");  // earlier phase
        EXPECT_GT(log.position("report"), log.position("integrate"));
        EXPECT_GT(log.position("report"), log.position("damage"));
    }
}

TEST(Scheduler, NonConflictingSystemsRunInParallel) {
    Registry registry;
    JobSystem jobs(2);
    Scheduler scheduler(registry, jobs);
    // Each system waits until the other has started: only possible if they overlap in time.
    std::atomic<int> arrived{0};
    std::atomic<bool> overlapped{true};
    auto rendezvous = [&](SystemContext&) {
        arrived.fetch_add(1);
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
        while (arrived.load() < 2) {
            if (std::chrono::steady_clock::now() > deadline) {
                overlapped = false;
                return;
            }
            std::this_thread::yield();
        }
    };
    scheduler.addSystem("a", Phase::Update, rendezvous).writes<Position>().reads<Velocity>();
    scheduler.addSystem("b", Phase::Update, rendezvous).writes<Health>().reads<Velocity>();
    ASSERT_EQ(scheduler.stages().size(), 1u);
    scheduler.run();
    EXPECT_TRUE(overlapped.load());
}

TEST(Scheduler, ResourceAccessesOrderSystems) {
    Registry registry;
    registry.resources().emplace<Time>();
    JobSystem jobs(2);
    Scheduler scheduler(registry, jobs);
    scheduler
        .addSystem("tick", Phase::Update,
                   [](SystemContext& ctx) { ++ctx.registry().resources().get<Time>().frame; })
        .writesResource<Time>();
    std::vector<int> seen;
    scheduler
        .addSystem("read time", Phase::Update,
                   [&](SystemContext& ctx) {
                       seen.push_back(ctx.registry().resources().get<Time>().frame);
                   })
        .readsResource<Time>();
    for (int i = 0; i < 5; ++i)
        scheduler.run();
    EXPECT_EQ(seen, (std::vector<int>{1, 2, 3, 4, 5}));
}

// Many entities, several systems in parallel, each writing its own components, plus chunked
// parallel iteration inside a system. Run under ThreadSanitizer to prove it race-free.
TEST(Scheduler, ParallelSystemsAreRaceFree) {
    Registry registry;
    registry.resources().emplace<Time>();
    registry.group<Position, Velocity>();
    for (int i = 0; i < 20'000; ++i) {
        const Entity e = registry.create();
        registry.emplace<Position>(e);
        registry.emplace<Velocity>(e, 1.0f, 2.0f, 3.0f);
        registry.emplace<Health>(e, 1000);
    }
    JobSystem jobs(3);
    Scheduler scheduler(registry, jobs);
    scheduler
        .addSystem("integrate", Phase::Update,
                   [](SystemContext& ctx) {
                       const float dt = ctx.registry().resources().get<Time>().delta;
                       ctx.parallelEach(
                           ctx.registry().view<Position, const Velocity>(),
                           [dt](Position& p, const Velocity& v) {
                               p.x += v.x * dt;
                               p.y += v.y * dt;
                               p.z += v.z * dt;
                           },
                           1024);
                   })
        .reads<Velocity>()
        .writes<Position>()
        .readsResource<Time>();
    scheduler
        .addSystem("decay", Phase::Update,
                   [](SystemContext& ctx) {
                       ctx.parallelEach(
                           ctx.registry().view<Health>(), [](Health& h) { --h.value; }, 1024);
                   })
        .writes<Health>();
    std::atomic<long> total{0};
    scheduler
        .addSystem("sum health", Phase::PostUpdate,
                   [&](SystemContext& ctx) {
                       ctx.parallelEach(ctx.registry().view<const Health>(), [&](const Health& h) {
                           total.fetch_add(h.value, std::memory_order_relaxed);
                       });
                   })
        .reads<Health>();
    for (int frame = 0; frame < 10; ++frame)
        scheduler.run();
    registry.view<const Position>().each([](const Position& p) {
        ASSERT_FLOAT_EQ(p.x, 5.0f);
        ASSERT_FLOAT_EQ(p.z, 15.0f);
    });
    registry.view<const Health>().each([](const Health& h) { ASSERT_EQ(h.value, 990); });
    EXPECT_EQ(total.load(), 20'000L * (999 + 990) * 10 / 2);
}

TEST(Scheduler, CommandsApplyAtSyncPoints) {
    Registry registry;
    JobSystem jobs(2);
    Scheduler scheduler(registry, jobs);
    std::size_t seenLaterInPhase = 99, seenByExclusive = 99, seenNextPhase = 99;
    scheduler
        .addSystem("spawn", Phase::Update,
                   [](SystemContext& ctx) {
                       for (int i = 0; i < 10; ++i) {
                           const Entity e = ctx.commands().create();
                           ctx.commands().emplace<Health>(e, i);
                       }
                   })
        .writes<Health>();
    scheduler
        .addSystem(
            "count in phase", Phase::Update,
            [&](SystemContext& ctx) { seenLaterInPhase = ctx.registry().view<Health>().size(); })
        .reads<Health>();
    scheduler
        .addSystem("exclusive", Phase::Update,
                   [&](SystemContext& ctx) {
                       seenByExclusive = ctx.registry().view<Health>().size();
                       ctx.registry().create();  // allowed: structure is unlocked
                   })
        .exclusive();
    scheduler
        .addSystem(
            "count next phase", Phase::PostUpdate,
            [&](SystemContext& ctx) { seenNextPhase = ctx.registry().view<Health>().size(); })
        .reads<Health>();
    scheduler.run();
    EXPECT_EQ(seenLaterInPhase, 0u);
    EXPECT_EQ(seenByExclusive, 10u);
    EXPECT_EQ(seenNextPhase, 10u);
    EXPECT_EQ(registry.aliveCount(), 11u);
}

TEST(Scheduler, ParallelCommandRecordingFromChunks) {
    Registry registry;
    for (int i = 0; i < 10'000; ++i)
        registry.emplace<Health>(registry.create(), i);
    JobSystem jobs(3);
    Scheduler scheduler(registry, jobs);
    scheduler
        .addSystem("cull odd", Phase::Update,
                   [](SystemContext& ctx) {
                       ctx.parallelEach(
                           ctx.registry().view<const Health>(),
                           [&ctx](Entity e, const Health& h) {
                               if (h.value % 2 == 1) ctx.commands().destroy(e);
                               if (h.value % 1000 == 0) {
                                   ctx.commands().emplace<Velocity>(ctx.commands().create());
                               }
                           },
                           256);
                   })
        .reads<Health>();
    scheduler.run();
    EXPECT_EQ(registry.view<Health>().size(), 5'000u);
    EXPECT_EQ(registry.view<Velocity>().size(), 10u);
}

TEST(Scheduler, DirectStructuralChangeInParallelStageIsRejected) {
    Registry registry;
    JobSystem jobs(1);
    Scheduler scheduler(registry, jobs);
    bool rejected = false;
    scheduler.addSystem("bad", Phase::Update, [&](SystemContext& ctx) {
#ifdef NDEBUG
        try {
            ctx.registry().create();
        } catch (const EcsError& error) {
            rejected = error.code() == EcsErrorCode::StructuralChangeWhileLocked;
        }
#else
        rejected = ctx.registry().structureLocked();
#endif
    });
    scheduler.run();
    EXPECT_TRUE(rejected);
    EXPECT_EQ(registry.aliveCount(), 0u);
}

TEST(Scheduler, TransformSystemKeepsDeclarationOrderWithWriters) {
    Registry registry;
    const Entity parent = registry.create();
    registry.emplace<LocalTransform>(parent);
    registry.emplace<WorldTransform>(parent);
    const Entity child = registry.create();
    registry.emplace<LocalTransform>(child, LocalTransform{{0, 1, 0}, {}, {1, 1, 1}});
    registry.emplace<WorldTransform>(child);
    ASSERT_EQ(setParent(registry, child, parent), ReparentResult::Ok);
    JobSystem jobs(2);
    Scheduler scheduler(registry, jobs);
    addTransformSystem(scheduler, Phase::Update);
    scheduler
        .addSystem("move", Phase::Update,
                   [parent](SystemContext& ctx) {
                       ctx.registry().patch<LocalTransform>(
                           parent, [](LocalTransform& t) { t.position.x += 1; });
                   })
        .writes<LocalTransform>();
    // Declared after propagation and conflicting with it: runs after it in the same phase,
    // so the world transform lags one frame. Run two frames and check the lag.
    scheduler.run();
    scheduler.run();
    EXPECT_FLOAT_EQ(registry.get<WorldTransform>(child).position().x, 1.0f);
    EXPECT_FLOAT_EQ(registry.get<LocalTransform>(parent).position.x, 2.0f);
}

}  // namespace
}  // namespace candela::ecs
