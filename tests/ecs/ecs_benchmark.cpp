// candela-bench-ecs: ECS throughput against plain std::vector baselines in the same binary.
// Every benchmark reports items per second; one item is one entity. Names are stable so
// results can be compared over time (see ecs/README.md for the measured table).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include <candela/ecs/hierarchy.h>
#include <candela/ecs/registry.h>
#include <candela/ecs/transform.h>
#include <candela/ecs/transform_propagation.h>

namespace {

using namespace candela::ecs;

struct Position {
    float x = 0, y = 0, z = 0;
};
struct Velocity {
    float x = 1, y = 1, z = 1;
};
struct Acceleration {
    float x = 0.5f, y = 0.5f, z = 0.5f;
};

constexpr float kDt = 1.0f / 60.0f;

// Reported as the "entities" counter: how many entities the loop visits, so the run can be
// checked against another library's benchmark of the same workload.
template <class Iterable>
void countVisited(benchmark::State& state, Iterable& iterable) {
    double visited = 0;
    iterable.each([&](auto&...) { ++visited; });
    state.counters["entities"] = visited;
}

void setItems(benchmark::State& state) {
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_Create(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    for (auto _ : state) {
        state.PauseTiming();
        auto registry = std::make_unique<Registry>();
        state.ResumeTiming();
        for (std::size_t i = 0; i < n; ++i)
            benchmark::DoNotOptimize(registry->create());
        state.PauseTiming();
        registry.reset();
        state.ResumeTiming();
    }
    setItems(state);
}
BENCHMARK(BM_Create)->Arg(1 << 20)->Unit(benchmark::kMillisecond);

// Creation in a warm registry: it already held n entities, destroyed (untimed) before each
// round, so the figure is the ECS's (slot reuse) and not the first touch of fresh pages that
// dominates the cold BM_Create above.
void BM_CreateWarm(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    Registry registry;
    std::vector<Entity> entities(n);
    for (Entity& e : entities)
        e = registry.create();
    for (auto _ : state) {
        state.PauseTiming();
        for (Entity e : entities)
            registry.destroy(e);
        state.ResumeTiming();
        for (Entity& e : entities)
            benchmark::DoNotOptimize(e = registry.create());
    }
    setItems(state);
}
BENCHMARK(BM_CreateWarm)->Arg(1 << 20)->Unit(benchmark::kMillisecond);

void BM_Destroy(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    std::vector<Entity> entities(n);
    for (auto _ : state) {
        state.PauseTiming();
        auto registry = std::make_unique<Registry>();
        for (Entity& e : entities) {
            e = registry->create();
            registry->emplace<Position>(e);
            registry->emplace<Velocity>(e);
        }
        state.ResumeTiming();
        for (Entity e : entities)
            registry->destroy(e);
        state.PauseTiming();
        registry.reset();
        state.ResumeTiming();
    }
    setItems(state);
}
BENCHMARK(BM_Destroy)->Arg(1 << 20)->Unit(benchmark::kMillisecond);

// One item = one entity gaining a component and losing it again.
void BM_AddRemove(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    Registry registry;
    std::vector<Entity> entities(n);
    for (Entity& e : entities) {
        e = registry.create();
        registry.emplace<Position>(e);
    }
    for (auto _ : state) {
        for (Entity e : entities)
            registry.emplace<Velocity>(e);
        for (Entity e : entities)
            registry.remove<Velocity>(e);
    }
    setItems(state);
}
BENCHMARK(BM_AddRemove)->Arg(1 << 14)->Arg(1 << 20)->Unit(benchmark::kMillisecond);

// Iteration benchmarks declare an owning group, the intended setup for hot loops: the pools
// then share one order and the view walks them as plain arrays. The _View variants run the
// same loop without a group (smallest pool walked, the others looked up by entity).
template <bool kGrouped>
void iterate2(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    Registry registry;
    if constexpr (kGrouped) registry.group<Position, Velocity>();
    for (std::size_t i = 0; i < n; ++i) {
        const Entity e = registry.create();
        registry.emplace<Position>(e);
        registry.emplace<Velocity>(e);
    }
    auto view = registry.view<Position, const Velocity>();
    countVisited(state, view);
    for (auto _ : state) {
        view.each([](Position& p, const Velocity& v) {
            p.x += v.x * kDt;
            p.y += v.y * kDt;
            p.z += v.z * kDt;
        });
        benchmark::ClobberMemory();
    }
    setItems(state);
}
void BM_Iterate2(benchmark::State& state) {
    iterate2<true>(state);
}
void BM_Iterate2_View(benchmark::State& state) {
    iterate2<false>(state);
}
BENCHMARK(BM_Iterate2)->Arg(1 << 20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Iterate2_View)->Arg(1 << 20)->Unit(benchmark::kMillisecond);

template <bool kGrouped>
void iterate3(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    Registry registry;
    if constexpr (kGrouped) registry.group<Position, Velocity, Acceleration>();
    for (std::size_t i = 0; i < n; ++i) {
        const Entity e = registry.create();
        registry.emplace<Position>(e);
        registry.emplace<Velocity>(e);
        registry.emplace<Acceleration>(e);
    }
    auto view = registry.view<Position, Velocity, const Acceleration>();
    countVisited(state, view);
    for (auto _ : state) {
        view.each([](Position& p, Velocity& v, const Acceleration& a) {
            v.x += a.x * kDt;
            v.y += a.y * kDt;
            v.z += a.z * kDt;
            p.x += v.x * kDt;
            p.y += v.y * kDt;
            p.z += v.z * kDt;
        });
        benchmark::ClobberMemory();
    }
    setItems(state);
}
void BM_Iterate3(benchmark::State& state) {
    iterate3<true>(state);
}
void BM_Iterate3_View(benchmark::State& state) {
    iterate3<false>(state);
}
BENCHMARK(BM_Iterate3)->Arg(1 << 20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Iterate3_View)->Arg(1 << 20)->Unit(benchmark::kMillisecond);

void BM_Get(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    Registry registry;
    std::vector<Entity> entities(n);
    for (Entity& e : entities) {
        e = registry.create();
        registry.emplace<Position>(e, 1.0f, 2.0f, 3.0f);
        registry.emplace<Velocity>(e);
    }
    {
        float sum = 0;  // reported: every lookup found its entity's value (y = 2)
        for (Entity e : entities)
            sum += registry.get<Position>(e).y;
        state.counters["sum"] = sum;
    }
    for (auto _ : state) {
        float sum = 0;
        for (Entity e : entities)
            sum += registry.get<Position>(e).y;
        benchmark::DoNotOptimize(sum);
    }
    setItems(state);
}
BENCHMARK(BM_Get)->Arg(1 << 20)->Unit(benchmark::kMillisecond);

// The unchecked storage-level accessor for hot loops (registry.storage<T>().get(e)).
void BM_GetUnchecked(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    Registry registry;
    std::vector<Entity> entities(n);
    for (Entity& e : entities) {
        e = registry.create();
        registry.emplace<Position>(e, 1.0f, 2.0f, 3.0f);
        registry.emplace<Velocity>(e);
    }
    const Storage<Position> positions = registry.storage<Position>();
    {
        float sum = 0;  // reported: every lookup found its entity's value (y = 2)
        for (Entity e : entities)
            sum += positions.get(e).y;
        state.counters["sum"] = sum;
    }
    for (auto _ : state) {
        float sum = 0;
        for (Entity e : entities)
            sum += positions.get(e).y;
        benchmark::DoNotOptimize(sum);
    }
    setItems(state);
}
BENCHMARK(BM_GetUnchecked)->Arg(1 << 20)->Unit(benchmark::kMillisecond);

// A forest: each root gets `fanout[0]` children, each of those `fanout[1]`, ... (BFS per root),
// until exactly `count` entities exist. {8, 3, 2} gives 81 entities and 4 levels per root.
std::vector<Entity> buildForest(Registry& registry, std::size_t count) {
    constexpr int kFanout[] = {8, 3, 2};
    std::vector<Entity> roots;
    std::size_t made = 0;
    auto spawn = [&](Entity parent) {
        const Entity e = registry.create();
        registry.emplace<LocalTransform>(e, LocalTransform{{0.5f, 1.0f, 0.0f}, {}, {1, 1, 1}});
        registry.emplace<WorldTransform>(e);
        if (!parent.isNull()) (void)setParent(registry, e, parent);
        ++made;
        return e;
    };
    while (made < count) {
        std::vector<Entity> level{spawn(kNullEntity)};
        roots.push_back(level.front());
        for (int fanout : kFanout) {
            std::vector<Entity> next;
            for (Entity parent : level) {
                for (int i = 0; i < fanout && made < count; ++i)
                    next.push_back(spawn(parent));
            }
            level = std::move(next);
        }
    }
    return roots;
}

// Every root moves each frame, so all 81,000 world matrices are recomputed.
void BM_Propagate(benchmark::State& state) {
    Registry registry;
    const std::vector<Entity> roots = buildForest(registry, std::size_t(state.range(0)));
    propagateTransforms(registry);
    // Workload check, reported as "wrong": every world translation is (depth + 1) x (0.5, 1, 0).
    double wrong = 0;
    registry.view<const HierarchyNode, const WorldTransform>().each(
        [&](const HierarchyNode& node, const WorldTransform& world) {
            const float expectY = float(node.depth + 1);
            if (std::abs(world.matrix.m[13] - expectY) > 1e-4f ||
                std::abs(world.matrix.m[12] - 0.5f * expectY) > 1e-4f)
                ++wrong;
        });
    state.counters["wrong"] = wrong;
    float t = 0;
    std::uint32_t recomputed = 0;
    for (auto _ : state) {
        t += kDt;
        for (Entity root : roots) {
            registry.patch<LocalTransform>(root, [&](LocalTransform& l) { l.position.x = t; });
        }
        recomputed = propagateTransforms(registry).recomputed;
    }
    state.counters["recomputed"] = recomputed;
    setItems(state);
}
BENCHMARK(BM_Propagate)->Arg(81000)->Unit(benchmark::kMicrosecond);

// Nothing changed: propagation must not walk the tree.
void BM_PropagateStatic(benchmark::State& state) {
    Registry registry;
    buildForest(registry, std::size_t(state.range(0)));
    propagateTransforms(registry);
    for (auto _ : state)
        benchmark::DoNotOptimize(propagateTransforms(registry));
    setItems(state);
}
BENCHMARK(BM_PropagateStatic)->Arg(127515)->Unit(benchmark::kMicrosecond);

// ---- Baselines: the same loops over plain std::vector structure-of-arrays ----------------

void BM_RawArrays_Iterate2(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    std::vector<Position> positions(n);
    std::vector<Velocity> velocities(n);
    for (auto _ : state) {
        Position* p = positions.data();
        const Velocity* v = velocities.data();
        for (std::size_t i = 0; i < n; ++i) {
            p[i].x += v[i].x * kDt;
            p[i].y += v[i].y * kDt;
            p[i].z += v[i].z * kDt;
        }
        benchmark::ClobberMemory();
    }
    setItems(state);
}
BENCHMARK(BM_RawArrays_Iterate2)->Arg(1 << 20)->Unit(benchmark::kMillisecond);

void BM_RawArrays_Iterate3(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    std::vector<Position> positions(n);
    std::vector<Velocity> velocities(n);
    std::vector<Acceleration> accelerations(n);
    for (auto _ : state) {
        Position* p = positions.data();
        Velocity* v = velocities.data();
        const Acceleration* a = accelerations.data();
        for (std::size_t i = 0; i < n; ++i) {
            v[i].x += a[i].x * kDt;
            v[i].y += a[i].y * kDt;
            v[i].z += a[i].z * kDt;
            p[i].x += v[i].x * kDt;
            p[i].y += v[i].y * kDt;
            p[i].z += v[i].z * kDt;
        }
        benchmark::ClobberMemory();
    }
    setItems(state);
}
BENCHMARK(BM_RawArrays_Iterate3)->Arg(1 << 20)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
