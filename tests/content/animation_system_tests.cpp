// The animation components and systems on real models: sampled poses reach the node
// entities, crossfades blend, joint matrices and bounds follow the skeleton, morph weights
// follow the file's keys, and a warm frame allocates nothing.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <new>

#include "candela/content/animation_sampling.h"
#include "candela/content/animation_systems.h"
#include "candela/content/components/mesh_instance.h"
#include "candela/content/gltf_loader.h"
#include "candela/content/model_instantiation.h"
#include "candela/content/skinning.h"
#include "candela/ecs/hierarchy.h"
#include "candela/ecs/transform_propagation.h"

// Counts every allocation in this test binary, so a test can assert a frame made none. Not in
// AddressSanitizer builds: ASan owns operator new there (and checks new/delete pairs itself).
namespace {
std::atomic<std::size_t> allocationCount{0};
}
#if !defined(__SANITIZE_ADDRESS__)
#define CANDELA_COUNTS_ALLOCATIONS 1
// The replacement pairs malloc with free; GCC, seeing the replaced operator new inlined into
// gtest's factories, takes the free for a mismatch.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
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
#endif

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

// Forward playback takes the inline path (sampleLinearInCursorInterval, the cursor's key
// interval or the next): frame after frame the entities hold exactly the general sampler's
// values at the player's time.
TEST(AnimationSystems, ForwardPlaybackPoseEqualsTheGeneralSamplerExactly) {
    const Model fox = loadModel("Fox");
    World world(fox);
    AnimationPlayer& player = world.player();
    const std::int32_t run = player.findClip("Run");
    player.play(run);
    const AnimationClip& clip = fox.animations[static_cast<std::size_t>(run)];
    // Fox's samplers share one key-time accessor: this compares the once-per-clip interval
    // path (sampleClip's shared key) with the general sampler.
    ASSERT_TRUE(clip.linearSharedTimes);
    // ...and every Run rotation interval holds a corrected nlerp, so the clip's rotations
    // sample four tracks at a time from its structure-of-arrays keys.
    ASSERT_FALSE(clip.sharedRotations.empty());
    ASSERT_EQ(
        clip.sharedRotations.rotationChannels.size() + clip.sharedRotations.otherChannels.size(),
        clip.channels.size());
    for (int frame = 0; frame < 60; ++frame) {
        world.frame(1.0f / 60.0f);
        for (const AnimationChannel& channel : clip.channels) {
            const ecs::Entity e = player.nodeEntities[static_cast<std::size_t>(channel.node)];
            const std::vector<float> expected = sampleChannel(clip, channel, player.time);
            const std::vector<float> got =
                localValue(world.registry.get<ecs::LocalTransform>(e), channel.property);
            for (std::size_t c = 0; c < expected.size(); ++c)
                ASSERT_EQ(got[c], expected[c]) << "frame " << frame << " node " << channel.node;
        }
    }
}

// Only a clip whose samplers are all LINEAR with bit-for-bit the same key times (two or more)
// takes the once-per-clip key search.
TEST(AnimationSystems, SharedKeyTimesNeedTheSameTimesAndLinearEverywhere) {
    AnimationClip clip;
    clip.samplers.resize(2);
    for (AnimationSampler& sampler : clip.samplers) {
        sampler.components = 3;
        sampler.times = {0.0f, 0.5f, 1.0f};
        sampler.values.assign(9, 0.0f);
    }
    markSharedKeyTimes(clip);
    EXPECT_TRUE(clip.linearSharedTimes);
    clip.samplers[1].times[1] = 0.25f;
    markSharedKeyTimes(clip);
    EXPECT_FALSE(clip.linearSharedTimes);
    clip.samplers[1].times[1] = 0.5f;
    clip.samplers[1].interpolation = Interpolation::Step;
    markSharedKeyTimes(clip);
    EXPECT_FALSE(clip.linearSharedTimes);
    clip.samplers[1].interpolation = Interpolation::Linear;
    for (AnimationSampler& sampler : clip.samplers)
        sampler.times = {0.0f};
    markSharedKeyTimes(clip);
    EXPECT_FALSE(clip.linearSharedTimes);
}

// The skeleton pass writes joints' worlds itself and leaves their locals unstamped: what it
// wrote must be exactly what propagation computes from those locals, and an entity attached
// under a joint (something else reading it) must still follow the joint.
TEST(AnimationSystems, SkeletonPassWorldsEqualPropagationAndAttachmentsFollow) {
    const Model fox = loadModel("Fox");
    World world(fox);
    AnimationPlayer& player = world.player();
    player.play(player.findClip("Run"));
    player.writeJointWorlds = true;  // every joint's world stored, to compare with propagation's
    const ecs::Entity head =
        player.nodeEntities[static_cast<std::size_t>(fox.skins[0].joints[6])];  // b_Head_05
    const ecs::Entity hat = world.registry.create();
    world.registry.emplace<ecs::LocalTransform>(hat, ecs::LocalTransform{{0, 10, 0}, {}, {}});
    world.registry.emplace<ecs::WorldTransform>(hat);
    ASSERT_EQ(ecs::setParent(world.registry, hat, head), ecs::ReparentResult::Ok);
    for (int f = 0; f < 4; ++f) {
        world.frame(0.07f);
        std::vector<std::pair<ecs::Entity, ecs::Mat4>> written;
        world.registry.view<const ecs::WorldTransform>().each(
            [&](ecs::Entity e, const ecs::WorldTransform& w) {
                written.push_back({e, w.matrix});
            });
        // Every local marked changed: propagation recomputes every world from the locals.
        for (const auto& [e, m] : written)
            if (world.registry.has<ecs::LocalTransform>(e))
                world.registry.markChanged<ecs::LocalTransform>(e);
        ecs::propagateTransforms(world.registry);
        for (const auto& [e, m] : written)
            EXPECT_EQ(world.registry.get<ecs::WorldTransform>(e).matrix, m) << "frame " << f;
        const ecs::Mat4 expectedHat = world.registry.get<ecs::WorldTransform>(head).matrix *
                                      world.registry.get<ecs::LocalTransform>(hat).matrix();
        const ecs::Vec3 got = world.registry.get<ecs::WorldTransform>(hat).position();
        EXPECT_NEAR(got.x, expectedHat(0, 3), 1e-4);
        EXPECT_NEAR(got.y, expectedHat(1, 3), 1e-4);
        EXPECT_NEAR(got.z, expectedHat(2, 3), 1e-4);
    }
}

// The default: joints only skins read keep their stored WorldTransform (the pass builds the
// skins from its own buffer). The skins must still equal those built from propagated worlds,
// including the frames where propagation recomputes part of the skeleton after the pass (an
// attachment's joint is stamped: updateSkins then composes the unwritten worlds from the
// locals), and an attachment still follows its joint.
TEST(AnimationSystems, JointWorldsOnlySkinsReadAreLeftUnwrittenAndSkinsStayExact) {
    const Model fox = loadModel("Fox");
    World world(fox);
    AnimationPlayer& player = world.player();
    player.play(player.findClip("Run"));
    ASSERT_FALSE(player.writeJointWorlds);
    const SkinData& skinData = fox.skins[0];
    const ecs::Entity tail = player.nodeEntities[static_cast<std::size_t>(skinData.joints[20])];
    const ecs::Entity head = player.nodeEntities[static_cast<std::size_t>(skinData.joints[6])];
    ecs::Entity skinned = ecs::kNullEntity;
    world.registry.view<const Skin>().each([&](ecs::Entity e, const Skin&) { skinned = e; });
    ASSERT_NE(skinned, ecs::kNullEntity);
    world.frame(0.07f);
    for (int f = 0; f < 6; ++f) {
        const ecs::Mat4 tailWorldBefore = world.registry.get<ecs::WorldTransform>(tail).matrix;
        if (f == 3) {  // an attachment from here on: its joint is written and stamped
            const ecs::Entity hat = world.registry.create();
            world.registry.emplace<ecs::LocalTransform>(hat,
                                                        ecs::LocalTransform{{0, 10, 0}, {}, {}});
            world.registry.emplace<ecs::WorldTransform>(hat);
            ASSERT_EQ(ecs::setParent(world.registry, hat, head), ecs::ReparentResult::Ok);
        }
        world.frame(0.07f);
        if (f < 3) {  // nothing reads the tail but the skin: its stored world stays as it was
            EXPECT_EQ(world.registry.get<ecs::WorldTransform>(tail).matrix, tailWorldBefore);
        }
        const std::vector<ecs::Mat4> built = world.registry.get<Skin>(skinned).jointMatrices;
        ASSERT_EQ(built.size(), skinData.joints.size());
        // Every local marked changed: propagation recomputes every world, and the skin is
        // rebuilt from them.
        world.registry.view<const ecs::LocalTransform>().each(
            [&](ecs::Entity e, const ecs::LocalTransform&) {
                world.registry.markChanged<ecs::LocalTransform>(e);
            });
        ecs::propagateTransforms(world.registry);
        Skin& skin = world.registry.get<Skin>(skinned);
        skin.worldsSkippedByPose = false;  // the stored worlds are all current now
        updateSkins(world.registry, world.jobs);
        for (std::size_t j = 0; j < built.size(); ++j)
            EXPECT_EQ(skin.jointMatrices[j], built[j]) << "frame " << f << " joint " << j;
        if (f >= 3) {
            world.registry.view<const ecs::HierarchyNode>().each(
                [&](ecs::Entity e, const ecs::HierarchyNode& node) {
                    if (node.parent != head) return;
                    const ecs::Mat4 expected =
                        world.registry.get<ecs::WorldTransform>(head).matrix *
                        world.registry.get<ecs::LocalTransform>(e).matrix();
                    const ecs::Vec3 got = world.registry.get<ecs::WorldTransform>(e).position();
                    EXPECT_NEAR(got.x, expected(0, 3), 1e-4);
                    EXPECT_NEAR(got.y, expected(1, 3), 1e-4);
                    EXPECT_NEAR(got.z, expected(2, 3), 1e-4);
                });
        }
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

// A paused player writes nothing and its skin is not rebuilt (its joint matrices stay as
// they were). Scrubbing the time applies the new pose.
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
    const std::vector<ecs::Mat4> pausedMatrices = skin->jointMatrices;
    world.frame(0.1f);
    world.frame(0.1f);
    EXPECT_FLOAT_EQ(player.time, 0.2f);
    EXPECT_EQ(world.registry.changeTick<ecs::LocalTransform>(
                  player.nodeEntities[static_cast<std::size_t>(fox.skins[0].joints[3])]),
              localTick)
        << "a paused player rewrote its pose";
    EXPECT_EQ(skin->builtFrom, built) << "a still skin was rebuilt";
    ASSERT_EQ(skin->jointMatrices.size(), pausedMatrices.size());
    for (std::size_t j = 0; j < skin->jointMatrices.size(); ++j)
        EXPECT_EQ(skin->jointMatrices[j], pausedMatrices[j]) << "joint " << j;
    player.time = 0.35f;  // scrub
    world.frame(0.1f);
    EXPECT_NE(skin->builtFrom, built);
}

// An independent double-precision reference: node globals composed straight from the Model's
// hierarchy and the sampled Walk channels, joint matrices inverse(mesh) * joint * inverse bind,
// linear blend skinning. Compared with what the ECS path (players, propagation, Skin) and
// deformPrimitive give, at ten times.
struct Matrix {
    double m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    friend Matrix operator*(const Matrix& a, const Matrix& b) {
        Matrix r;
        for (int c = 0; c < 4; ++c)
            for (int i = 0; i < 4; ++i) {
                double v = 0;
                for (int k = 0; k < 4; ++k)
                    v += a.m[k * 4 + i] * b.m[c * 4 + k];
                r.m[c * 4 + i] = v;
            }
        return r;
    }
};

Matrix trs(const ecs::LocalTransform& t) {
    const double x = t.rotation.x, y = t.rotation.y, z = t.rotation.z, w = t.rotation.w;
    const double n = std::sqrt(x * x + y * y + z * z + w * w);
    const double qx = x / n, qy = y / n, qz = z / n, qw = w / n;
    Matrix r;
    const double rot[9] = {
        1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy + qw * qz),     2 * (qx * qz - qw * qy),
        2 * (qx * qy - qw * qz),     1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz + qw * qx),
        2 * (qx * qz + qw * qy),     2 * (qy * qz - qw * qx),     1 - 2 * (qx * qx + qy * qy)};
    const double scale[3] = {t.scale.x, t.scale.y, t.scale.z};
    for (int c = 0; c < 3; ++c)
        for (int i = 0; i < 3; ++i)
            r.m[c * 4 + i] = rot[c * 3 + i] * scale[c];
    r.m[12] = t.position.x;
    r.m[13] = t.position.y;
    r.m[14] = t.position.z;
    return r;
}

Matrix affineInverse(const Matrix& a) {
    const double* m = a.m;
    const double det = m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2]) +
                       m[8] * (m[1] * m[6] - m[5] * m[2]);
    Matrix r;
    r.m[0] = (m[5] * m[10] - m[9] * m[6]) / det;
    r.m[4] = -(m[4] * m[10] - m[8] * m[6]) / det;
    r.m[8] = (m[4] * m[9] - m[8] * m[5]) / det;
    r.m[1] = -(m[1] * m[10] - m[9] * m[2]) / det;
    r.m[5] = (m[0] * m[10] - m[8] * m[2]) / det;
    r.m[9] = -(m[0] * m[9] - m[8] * m[1]) / det;
    r.m[2] = (m[1] * m[6] - m[5] * m[2]) / det;
    r.m[6] = -(m[0] * m[6] - m[4] * m[2]) / det;
    r.m[10] = (m[0] * m[5] - m[4] * m[1]) / det;
    for (int i = 0; i < 3; ++i)
        r.m[12 + i] = -(r.m[i] * m[12] + r.m[4 + i] * m[13] + r.m[8 + i] * m[14]);
    return r;
}

TEST(AnimationSystems, FoxWalkSkinningMatchesADoublePrecisionReference) {
    const Model fox = loadModel("Fox");
    World world(fox);
    AnimationPlayer& player = world.player();
    const std::int32_t walk = player.findClip("Walk");
    const AnimationClip& clip = fox.animations[static_cast<std::size_t>(walk)];
    player.play(walk);
    player.playing = false;  // scrubbed: time set directly, as an editor would
    std::int32_t meshNode = -1;
    for (std::size_t n = 0; n < fox.nodes.size(); ++n)
        if (fox.nodes[n].skin == 0) meshNode = static_cast<std::int32_t>(n);
    ASSERT_GE(meshNode, 0);
    const SkinData& skinData = fox.skins[0];
    const Primitive& primitive =
        fox.meshes[static_cast<std::size_t>(fox.nodes[static_cast<std::size_t>(meshNode)].mesh)]
            .primitives[0];
    float size = 0;
    for (int a = 0; a < 3; ++a)
        size = std::max(size, primitive.boundsMax[a] - primitive.boundsMin[a]);
    double worst = 0;
    DeformedVertices deformed;
    for (int step = 0; step < 10; ++step) {
        const float time = clip.duration * (0.05f + 0.1f * static_cast<float>(step));
        player.time = time;
        world.frame(0.0f);
        // Reference pose.
        std::vector<ecs::LocalTransform> local(fox.nodes.size());
        for (std::size_t n = 0; n < fox.nodes.size(); ++n) {
            const Transform& t = fox.nodes[n].local;
            local[n] = {{t.translation[0], t.translation[1], t.translation[2]},
                        {t.rotation[0], t.rotation[1], t.rotation[2], t.rotation[3]},
                        {t.scale[0], t.scale[1], t.scale[2]}};
        }
        for (const AnimationChannel& channel : clip.channels) {
            const std::vector<float> v = sampleChannel(clip, channel, time);
            ecs::LocalTransform& l = local[static_cast<std::size_t>(channel.node)];
            if (channel.property == AnimatedProperty::Translation) l.position = {v[0], v[1], v[2]};
            if (channel.property == AnimatedProperty::Rotation)
                l.rotation = {v[0], v[1], v[2], v[3]};
            if (channel.property == AnimatedProperty::Scale) l.scale = {v[0], v[1], v[2]};
        }
        auto global = [&](std::int32_t node) {
            Matrix g;
            for (std::int32_t n = node; n != kNoIndex;
                 n = fox.nodes[static_cast<std::size_t>(n)].parent)
                g = trs(local[static_cast<std::size_t>(n)]) * g;
            return g;
        };
        const Matrix toMesh = affineInverse(global(meshNode));
        std::vector<Matrix> joints;
        for (std::size_t j = 0; j < skinData.joints.size(); ++j) {
            Matrix inverseBind;
            for (int i = 0; i < 16; ++i)
                inverseBind.m[i] = skinData.inverseBindMatrices[j][static_cast<std::size_t>(i)];
            joints.push_back(toMesh * global(skinData.joints[j]) * inverseBind);
        }
        // Engine path.
        const Skin& skin =
            world.registry.get<Skin>(player.nodeEntities[static_cast<std::size_t>(meshNode)]);
        deformPrimitive(primitive, skin.jointMatrices, {}, deformed);
        for (std::size_t v = 0; v < primitive.positions.size(); ++v) {
            double p[3] = {0, 0, 0};
            for (int c = 0; c < 4; ++c) {
                const Matrix& m = joints[primitive.joints[v][c]];
                const double w = primitive.weights[v][c];
                for (int i = 0; i < 3; ++i)
                    p[i] += w * (m.m[i] * primitive.positions[v][0] +
                                 m.m[4 + i] * primitive.positions[v][1] +
                                 m.m[8 + i] * primitive.positions[v][2] + m.m[12 + i]);
            }
            for (int i = 0; i < 3; ++i)
                worst = std::max(worst, std::fabs(p[i] - deformed.positions[v][i]));
        }
    }
    // The bound, 1e-4 in the file's units (metres), even though the Fox is about
    // 150 units long there (measured: 2.5e-5).
    std::printf("Fox Walk, 10 times: largest |engine - reference| = %.3g units (model size %.1f)\n",
                worst, size);
    EXPECT_LT(worst, 1e-4);
}

TEST(AnimationSystems, WarmFramesAllocateNothing) {
#if !defined(CANDELA_COUNTS_ALLOCATIONS)
    GTEST_SKIP() << "allocations are not counted in AddressSanitizer builds";
#endif
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
