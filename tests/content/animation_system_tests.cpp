// The animation components and systems on real models: sampled poses reach the node
// entities, crossfades blend, joint matrices and bounds follow the skeleton, morph weights
// follow the file's keys, and a warm frame allocates nothing.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <new>

#include "candela/content/animation_sampling.h"
#include "candela/content/animation_systems.h"
#include "candela/content/components/mesh_instance.h"
#include "candela/content/gltf_loader.h"
#include "candela/content/model_instantiation.h"
#include "candela/content/skinning.h"
#include "candela/ecs/transform_propagation.h"

// Counts every allocation in this test binary, so a test can assert a frame made none.
namespace {
std::atomic<std::size_t> allocationCount{0};
}
void* operator new(std::size_t size) {
    allocationCount.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}

namespace candela::content {
namespace {

Model loadModel(const std::string& name) {
    Diagnostics diagnostics;
    auto loaded =
        loadGltf(std::filesystem::path(CANDELA_SHARED_ASSETS) / "models" / name / (name + ".glb"),
                 diagnostics);
    EXPECT_TRUE(loaded && !diagnostics.hasErrors()) << diagnostics.toString();
    return loaded ? std::move(*loaded) : Model{};
}

struct World {
    ecs::Registry registry;
    ecs::JobSystem jobs{1};
    ecs::Entity playerEntity = ecs::kNullEntity;

    explicit World(const Model& model) {
        const auto created = instantiateModel(registry, model);
        for (ecs::Entity e : created)
            if (registry.has<AnimationPlayer>(e)) playerEntity = e;
    }
    AnimationPlayer& player() { return registry.get<AnimationPlayer>(playerEntity); }
    void frame(float seconds) {
        advanceAnimationPlayers(registry, jobs, seconds);
        ecs::propagateTransforms(registry);
        updateSkins(registry, jobs);
    }
};

std::vector<float> sampleChannel(const AnimationClip& clip, const AnimationChannel& channel,
                                 float time) {
    std::vector<float> out(channel.property == AnimatedProperty::Rotation ? 4 : 3);
    sampleAnimation(clip.samplers[static_cast<std::size_t>(channel.sampler)], channel.property,
                    clipTime(time, clip.duration, true), out);
    return out;
}

std::vector<float> localValue(const ecs::LocalTransform& t, AnimatedProperty property) {
    switch (property) {
        case AnimatedProperty::Translation:
            return {t.position.x, t.position.y, t.position.z};
        case AnimatedProperty::Rotation:
            return {t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w};
        default:
            return {t.scale.x, t.scale.y, t.scale.z};
    }
}

TEST(AnimationSystems, FoxWalkPoseReachesTheNodeEntities) {
    const Model fox = loadModel("Fox");
    World world(fox);
    ASSERT_NE(world.playerEntity, ecs::kNullEntity);
    AnimationPlayer& player = world.player();
    const std::int32_t walk = player.findClip("Walk");
    ASSERT_GE(walk, 0);
    player.play(walk);
    world.frame(0.5f);
    EXPECT_FLOAT_EQ(player.time, 0.5f);
    const AnimationClip& clip = fox.animations[static_cast<std::size_t>(walk)];
    for (const AnimationChannel& channel : clip.channels) {
        const ecs::Entity e = player.nodeEntities[static_cast<std::size_t>(channel.node)];
        const std::vector<float> expected = sampleChannel(clip, channel, 0.5f);
        const std::vector<float> got =
            localValue(world.registry.get<ecs::LocalTransform>(e), channel.property);
        for (std::size_t c = 0; c < expected.size(); ++c)
            EXPECT_NEAR(got[c], expected[c], 1e-6) << "node " << channel.node;
    }
}

TEST(AnimationSystems, CrossfadeBlendsThenSwitchesClips) {
    const Model fox = loadModel("Fox");
    World world(fox);
    AnimationPlayer& player = world.player();
    const std::int32_t walk = player.findClip("Walk");
    const std::int32_t run = player.findClip("Run");
    player.play(walk);
    world.frame(0.25f);
    player.crossfade(run, 0.5f);
    world.frame(0.25f);  // half way: walk at 0.5 s, run at 0.25 s, weight 0.5
    EXPECT_FLOAT_EQ(player.fadeWeight(), 0.5f);
    const AnimationClip& walkClip = fox.animations[static_cast<std::size_t>(walk)];
    const AnimationClip& runClip = fox.animations[static_cast<std::size_t>(run)];
    int checked = 0;
    for (const AnimationChannel& channel : walkClip.channels) {
        if (channel.property != AnimatedProperty::Translation) continue;
        for (const AnimationChannel& other : runClip.channels) {
            if (other.node != channel.node || other.property != channel.property) continue;
            const auto a = sampleChannel(walkClip, channel, 0.5f);
            const auto b = sampleChannel(runClip, other, 0.25f);
            const auto got =
                localValue(world.registry.get<ecs::LocalTransform>(
                               player.nodeEntities[static_cast<std::size_t>(channel.node)]),
                           channel.property);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(got[c], 0.5f * (a[c] + b[c]), 1e-5);
            ++checked;
        }
    }
    EXPECT_GT(checked, 0);
    world.frame(0.3f);  // past the fade
    EXPECT_EQ(player.clip, run);
    EXPECT_EQ(player.nextClip, -1);
    EXPECT_NEAR(player.time, 0.55f, 1e-5);
}

TEST(AnimationSystems, RestPoseJointMatricesAreIdentity) {
    const Model fox = loadModel("Fox");
    World world(fox);
    world.player().play(-1);  // no clip: nodes keep the file's rest pose (the bind pose here)
    world.frame(0.0f);
    int skins = 0;
    world.registry.view<Skin>().each([&](ecs::Entity, Skin& skin) {
        ++skins;
        for (const ecs::Mat4& m : skin.jointMatrices)
            for (int i = 0; i < 16; ++i)
                EXPECT_NEAR(m.m[i], ecs::Mat4::identity().m[i], 1e-4);
    });
    EXPECT_EQ(skins, 1);
}

// The skinned vertices (plain CPU skinning) stay inside the skin's bounds at every time.
TEST(AnimationSystems, SkinBoundsCoverTheDeformedMesh) {
    const Model fox = loadModel("Fox");
    World world(fox);
    world.player().play(world.player().findClip("Run"));
    DeformedVertices deformed;
    for (int step = 0; step < 10; ++step) {
        world.frame(0.1f);
        world.registry.view<Skin, MeshInstance>().each([&](ecs::Entity, Skin& skin,
                                                           MeshInstance& mesh) {
            ASSERT_TRUE(skin.boundsValid);
            for (const Primitive& p : fox.meshes[static_cast<std::size_t>(mesh.mesh)].primitives) {
                deformPrimitive(p, skin.jointMatrices, {}, deformed);
                for (const Float3& v : deformed.positions) {
                    EXPECT_GE(v[0], skin.boundsMin.x - 1e-4f);
                    EXPECT_LE(v[0], skin.boundsMax.x + 1e-4f);
                    EXPECT_GE(v[1], skin.boundsMin.y - 1e-4f);
                    EXPECT_LE(v[1], skin.boundsMax.y + 1e-4f);
                    EXPECT_GE(v[2], skin.boundsMin.z - 1e-4f);
                    EXPECT_LE(v[2], skin.boundsMax.z + 1e-4f);
                }
            }
        });
    }
}

TEST(AnimationSystems, MorphWeightsFollowTheFilesKeys) {
    const Model cube = loadModel("AnimatedMorphCube");
    World world(cube);
    const AnimationClip& clip = cube.animations[0];
    const AnimationChannel* weights = nullptr;
    for (const AnimationChannel& c : clip.channels)
        if (c.property == AnimatedProperty::Weights) weights = &c;
    ASSERT_NE(weights, nullptr);
    const AnimationSampler& sampler = clip.samplers[static_cast<std::size_t>(weights->sampler)];
    const ecs::Entity meshEntity =
        world.player().nodeEntities[static_cast<std::size_t>(weights->node)];
    const std::size_t n = sampler.components;
    const std::size_t stride = sampler.interpolation == Interpolation::CubicSpline ? 3 * n : n;
    const std::size_t offset = sampler.interpolation == Interpolation::CubicSpline ? n : 0;
    float now = 0;
    for (std::size_t k = 0; k < sampler.times.size(); k += 7) {
        world.frame(sampler.times[k] - now);
        now = sampler.times[k];
        const MorphWeights& morph = world.registry.get<MorphWeights>(meshEntity);
        ASSERT_EQ(morph.weights.size(), n);
        for (std::size_t c = 0; c < n; ++c)
            EXPECT_NEAR(morph.weights[c], sampler.values[k * stride + offset + c], 1e-5)
                << "key " << k << " at " << now << " s";
    }
}

// A paused player writes nothing and its skin is not rebuilt; the previous-frame matrices
// catch up with the current ones (no motion). Scrubbing the time applies the new pose.
TEST(AnimationSystems, PausedPlayerAndStillSkinCostNothing) {
    const Model fox = loadModel("Fox");
    World world(fox);
    AnimationPlayer& player = world.player();
    player.play(player.findClip("Run"));
    world.frame(0.1f);
    world.frame(0.1f);
    player.playing = false;
    world.frame(0.1f);
    const ecs::Tick localTick = world.registry.changeTick<ecs::LocalTransform>(
        player.nodeEntities[static_cast<std::size_t>(fox.skins[0].joints[3])]);
    Skin* skin = nullptr;
    world.registry.view<Skin>().each([&](ecs::Entity, Skin& s) { skin = &s; });
    ASSERT_NE(skin, nullptr);
    const ecs::Tick built = skin->builtFrom;
    world.frame(0.1f);
    world.frame(0.1f);
    EXPECT_FLOAT_EQ(player.time, 0.2f);
    EXPECT_EQ(world.registry.changeTick<ecs::LocalTransform>(
                  player.nodeEntities[static_cast<std::size_t>(fox.skins[0].joints[3])]),
              localTick)
        << "a paused player rewrote its pose";
    EXPECT_EQ(skin->builtFrom, built) << "a still skin was rebuilt";
    EXPECT_TRUE(skin->previousIsCurrent);
    for (std::size_t j = 0; j < skin->jointMatrices.size(); ++j)
        EXPECT_EQ(skin->jointMatrices[j], skin->previousJointMatrices[j]);
    player.time = 0.35f;  // scrub
    world.frame(0.1f);
    EXPECT_NE(skin->builtFrom, built);
}

TEST(AnimationSystems, WarmFramesAllocateNothing) {
    const Model fox = loadModel("Fox");
    World world(fox);
    world.player().play(world.player().findClip("Walk"));
    world.frame(0.016f);
    world.player().crossfade(world.player().findClip("Run"), 1.0f);
    world.frame(0.016f);
    world.frame(0.016f);
    const std::size_t before = allocationCount.load();
    for (int i = 0; i < 20; ++i) {
        advanceAnimationPlayers(world.registry, world.jobs, 0.016f);
        ecs::propagateTransforms(world.registry);
        updateSkins(world.registry, world.jobs);
    }
    EXPECT_EQ(allocationCount.load() - before, 0u);
    EXPECT_GE(world.player().nextClip, 0) << "still crossfading: the blend path was measured";
}

}  // namespace
}  // namespace candela::content
