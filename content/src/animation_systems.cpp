#include "candela/content/animation_systems.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "candela/content/animation_sampling.h"
#include "candela/content/components/mesh_instance.h"
#include "candela/content/model.h"
#include "candela/ecs/hierarchy.h"
#include "joint_matrices.h"
#include "skeleton_pose_pass.h"

namespace candela::content {
namespace {

ecs::LocalTransform restPose(const Node& node) {
    const Transform& t = node.local;
    return {{t.translation[0], t.translation[1], t.translation[2]},
            {t.rotation[0], t.rotation[1], t.rotation[2], t.rotation[3]},
            {t.scale[0], t.scale[1], t.scale[2]}};
}

const std::vector<float>* restWeights(const Model& model, const Node& node) {
    if (node.mesh == kNoIndex) return nullptr;
    const Mesh& mesh = model.meshes[static_cast<std::size_t>(node.mesh)];
    if (mesh.defaultWeights.empty()) return nullptr;
    return node.weights.size() == mesh.defaultWeights.size() ? &node.weights : &mesh.defaultWeights;
}

// Sizes the scratch once per player (and again only if the model changes).
void prepareScratch(AnimationPlayer& player) {
    const Model& model = *player.model;
    AnimationPlayer::Scratch& s = player.scratch;
    if (s.pose.size() == model.nodes.size() && s.weightOffset.size() == model.nodes.size() + 1)
        return;
    std::size_t channels = 0;
    for (const AnimationClip& clip : model.animations)
        channels = std::max(channels, clip.channels.size());
    s.cursors.assign(channels, 0);
    s.blendCursors.assign(channels, 0);
    s.pose.resize(model.nodes.size());
    s.blendPose.resize(model.nodes.size());
    s.touched.assign(model.nodes.size() > kThreadTouchedNodes ? model.nodes.size() : 0, 0);
    s.weightOffset.resize(model.nodes.size() + 1);
    std::uint32_t offset = 0;
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        s.weightOffset[n] = offset;
        if (const auto* w = restWeights(model, model.nodes[n]))
            offset += static_cast<std::uint32_t>(w->size());
    }
    s.weightOffset[model.nodes.size()] = offset;
    s.weights.resize(offset);
    s.blendWeights.resize(offset);
    s.restPose.resize(model.nodes.size());
    s.restWeights.resize(offset);
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        s.restPose[n] = restPose(model.nodes[n]);
        if (const auto* w = restWeights(model, model.nodes[n]))
            std::copy(w->begin(), w->end(), s.restWeights.begin() + s.weightOffset[n]);
    }
}

// Copies, not conversions per node: the rest pose was converted once by prepareScratch.
void resetToRest(const AnimationPlayer::Scratch& s, std::vector<ecs::LocalTransform>& pose,
                 std::vector<float>& weights) {
    std::copy(s.restPose.begin(), s.restPose.end(), pose.begin());
    std::copy(s.restWeights.begin(), s.restWeights.end(), weights.begin());
}

// The clip's shared interval (`shared`: key sharedKey at parameter sharedT), else the channel's
// cursor interval or the next (forward playback); false: the general sampler's case (clamped,
// exact slerp, not LINEAR). Always inlined: a call per channel costs as much as the sample.
[[gnu::always_inline]] inline bool sampleInline(bool shared, std::size_t sharedKey, float sharedT,
                                                float t, const AnimationSampler& sampler,
                                                bool rotation, float* out, std::uint32_t& cursor) {
    return (shared && sampleLinearAt(sampler, rotation, sharedKey, sharedT, out)) ||
           sampleLinearInCursorInterval(sampler, rotation, t, out, cursor);
}

// `poseAt(node)`: where node's LocalTransform goes.
template <class PoseAt>
void sampleClip(const Model& model, std::int32_t clipIndex, float time, bool loop,
                AnimationPlayer::Scratch& s, std::uint8_t* touched, PoseAt&& poseAt,
                std::vector<float>& weights, std::vector<std::uint32_t>& cursors) {
    if (clipIndex < 0 || static_cast<std::size_t>(clipIndex) >= model.animations.size()) return;
    const AnimationClip& clip = model.animations[static_cast<std::size_t>(clipIndex)];
    const float t = clipTime(time, clip.duration, loop);
    // One key search for the whole clip where its samplers share their key times: the
    // interval k and its parameter, as each channel would find them (channel 0's cursor).
    bool shared = false;
    std::size_t sharedKey = 0;
    float sharedT = 0;
    if (clip.linearSharedTimes && !cursors.empty()) {
        const std::vector<float>& times = clip.samplers.front().times;
        std::size_t k = cursors[0];
        if (!(k + 1 < times.size() && times[k] <= t && t < times[k + 1] && t > times[0]))
            k = keyIntervalAt(times, t, cursors[0]);
        if (t > times.front() && k + 1 < times.size()) {  // else clamped: each channel's own
            shared = true;
            sharedKey = k;
            sharedT = (t - times[k]) / (times[k + 1] - times[k]);
            cursors[0] = static_cast<std::uint32_t>(k);
        }
    }
    if (shared && !clip.sharedRotations.empty()) {
        // Keys laid out four tracks side by side: each animated node starts from rest (as
        // below, at its first channel), then four rotations sample and normalise at a time,
        // then the translations and scales; the same floats as the per-channel loop.
        const SharedKeyRotations& plan = clip.sharedRotations;
        for (const std::uint32_t node : plan.nodes) {
            if (touched[node] & kTransformTouched) continue;
            poseAt(node) = restPose(model.nodes[node]);
            touched[node] |= kTransformTouched;
        }
        sampleSharedRotations(plan, sharedKey, sharedT, [&](std::uint32_t c) {
            return &poseAt(static_cast<std::size_t>(clip.channels[c].node)).rotation.x;
        });
        for (const std::uint32_t c : plan.otherChannels) {
            const AnimationChannel& channel = clip.channels[c];
            const AnimationSampler& sampler =
                clip.samplers[static_cast<std::size_t>(channel.sampler)];
            ecs::LocalTransform& local = poseAt(static_cast<std::size_t>(channel.node));
            sampleLinearAt(sampler, false, sharedKey, sharedT,
                           channel.property == AnimatedProperty::Translation ? &local.position.x
                                                                             : &local.scale.x);
        }
        return;
    }
    // Rotations are normalised four at a time (SSE2), the same values as one by one.
    std::array<float*, 4> unnormalised{};
    std::size_t pending = 0;
    for (std::size_t c = 0; c < clip.channels.size(); ++c) {
        const AnimationChannel& channel = clip.channels[c];
        std::uint32_t& cursor = cursors[c];
        const auto node = static_cast<std::size_t>(channel.node);
        const AnimationSampler& sampler = clip.samplers[static_cast<std::size_t>(channel.sampler)];
        ecs::LocalTransform& local = poseAt(node);
        // A node's first channel this frame starts it from the rest pose (the model's, shared
        // by every instance and so in cache even with thousands of players; the player's own
        // converted copy is not), for the properties no channel animates.
        if (channel.property != AnimatedProperty::Weights && !(touched[node] & kTransformTouched))
            local = restPose(model.nodes[node]);
        switch (channel.property) {
            case AnimatedProperty::Translation:
                if (!sampleInline(shared, sharedKey, sharedT, t, sampler, false, &local.position.x,
                                  cursor))
                    sampleAnimation(sampler, channel.property, t, std::span(&local.position.x, 3),
                                    cursor);
                touched[node] |= kTransformTouched;
                break;
            case AnimatedProperty::Rotation:
                if (!sampleInline(shared, sharedKey, sharedT, t, sampler, true, &local.rotation.x,
                                  cursor))
                    sampleAnimationUnnormalised(sampler, channel.property, t,
                                                std::span(&local.rotation.x, 4), cursor);
                touched[node] |= kTransformTouched;
                // Queued after each write, so whatever a channel wrote last is normalised.
                unnormalised[pending++] = &local.rotation.x;
                if (pending == unnormalised.size()) {
                    normalizeQuaternions(unnormalised);
                    pending = 0;
                }
                break;
            case AnimatedProperty::Scale:
                if (!sampleInline(shared, sharedKey, sharedT, t, sampler, false, &local.scale.x,
                                  cursor))
                    sampleAnimation(sampler, channel.property, t, std::span(&local.scale.x, 3),
                                    cursor);
                touched[node] |= kTransformTouched;
                break;
            case AnimatedProperty::Weights: {
                const std::uint32_t begin = s.weightOffset[node];
                const std::uint32_t count = s.weightOffset[node + 1] - begin;
                if (count != sampler.components) break;  // the loader checked; defensive
                sampleAnimation(sampler, channel.property, t,
                                std::span(weights).subspan(begin, count), cursor);
                touched[node] |= kWeightsTouched;
                break;
            }
        }
    }
    normalizeQuaternions(std::span<float* const>(unnormalised.data(), pending));
}

ecs::Vec3 lerp(ecs::Vec3 a, ecs::Vec3 b, float t) {
    return a + (b - a) * t;
}

// Normalised lerp along the shorter arc: for blending two poses it is as good as slerp and
// much cheaper (what most engines blend with).
ecs::Quat nlerp(ecs::Quat a, ecs::Quat b, float t) {
    const float sign = a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w < 0 ? -1.0f : 1.0f;
    return ecs::normalize({a.x + (sign * b.x - a.x) * t, a.y + (sign * b.y - a.y) * t,
                           a.z + (sign * b.z - a.z) * t, a.w + (sign * b.w - a.w) * t});
}

// `pools`: the transform pools, fetched once per frame.
void advancePlayer(ecs::Registry& registry, const TransformPools& pools, AnimationPlayer& player,
                   float deltaSeconds) {
    if (player.model == nullptr) return;
    const Model& model = *player.model;
    prepareScratch(player);
    AnimationPlayer::Scratch& s = player.scratch;
    const float step = player.playing ? deltaSeconds * player.speed : 0.0f;
    player.time += step;
    if (player.nextClip >= 0) {
        player.nextTime += step;
        if (player.playing) player.fadeElapsed += deltaSeconds;
        if (player.fadeElapsed >= player.fadeDuration) {
            player.clip = player.nextClip;
            player.time = player.nextTime;
            player.nextClip = -1;
            player.fadeElapsed = player.fadeDuration = player.nextTime = 0;
        }
    }
    // Keep the time small while looping so float precision does not decay over hours.
    if (player.loop && player.clip >= 0 &&
        static_cast<std::size_t>(player.clip) < model.animations.size()) {
        player.time = clipTime(player.time, model.animations[player.clip].duration, true);
    }

    if (s.applied && player.nextClip < 0 && s.appliedClip == player.clip &&
        s.appliedTime == player.time) {
        return;  // paused (or speed 0) and not scrubbed: the entities already hold this pose
    }
    s.applied = player.nextClip < 0;  // a crossfade always rewrites (its weight moves)
    s.appliedClip = player.clip;
    s.appliedTime = player.time;
    // Which nodes this frame's clips animate: per frame only, so a model of usual size keeps
    // the flags in the thread's buffer (one block fewer per player to fetch).
    thread_local std::uint8_t threadTouched[kThreadTouchedNodes];
    std::uint8_t* const touched =
        model.nodes.size() <= kThreadTouchedNodes ? threadTouched : s.touched.data();
    std::fill(touched, touched + model.nodes.size(), std::uint8_t{0});
    // Nodes no channel touches keep their entity's transform (the skeleton pass reads it), so
    // only a crossfade, where a node one clip leaves alone blends from its rest pose, needs
    // the whole rest pose; otherwise sampleClip starts each animated node from rest itself.
    if (player.nextClip >= 0) resetToRest(s, s.pose, s.weights);
    auto inScratch = [](std::vector<ecs::LocalTransform>& pose) {
        return [&pose](std::size_t node) -> ecs::LocalTransform& { return pose[node]; };
    };
    // Without a crossfade (nothing to blend), where the skeleton pass writes worlds itself,
    // the pose goes straight into the node entities' LocalTransform: no scratch pose to
    // write, read back and copy.
    const bool poseInLocals = player.nextClip < 0 && prepareSkeletonPose(registry, pools, player);
    if (poseInLocals) {
        ecs::LocalTransform* locals = pools.locals->typedData<ecs::LocalTransform>();
        const std::uint32_t* localIndex = s.localIndex.data();
        ecs::LocalTransform* pose = s.pose.data();
        sampleClip(
            model, player.clip, player.time, player.loop, s, touched,
            [&](std::size_t node) -> ecs::LocalTransform& {
                const std::uint32_t index = localIndex[node];
                return index != ecs::ComponentPool::kAbsent ? locals[index] : pose[node];
            },
            s.weights, s.cursors);
    } else {
        sampleClip(model, player.clip, player.time, player.loop, s, touched, inScratch(s.pose),
                   s.weights, s.cursors);
    }
    const float fade = player.fadeWeight();
    if (player.nextClip >= 0) {
        resetToRest(s, s.blendPose, s.blendWeights);
        sampleClip(model, player.nextClip, player.nextTime, player.loop, s, touched,
                   inScratch(s.blendPose), s.blendWeights, s.blendCursors);
        for (std::size_t n = 0; n < s.pose.size(); ++n) {
            if (touched[n] == 0) continue;
            ecs::LocalTransform& a = s.pose[n];
            const ecs::LocalTransform& b = s.blendPose[n];
            a.position = lerp(a.position, b.position, fade);
            a.rotation = nlerp(a.rotation, b.rotation, fade);
            a.scale = lerp(a.scale, b.scale, fade);
        }
        for (std::size_t i = 0; i < s.weights.size(); ++i)
            s.weights[i] += (s.blendWeights[i] - s.weights[i]) * fade;
    }

    writeSkeletonPose(registry, pools, player, touched, poseInLocals);
    if (s.weights.empty()) return;  // no morph targets in the model: no weights to write
    for (std::size_t n = 0; n < s.pose.size() && n < player.nodeEntities.size(); ++n) {
        const ecs::Entity e = player.nodeEntities[n];
        if (!(touched[n] & kWeightsTouched) || e == ecs::kNullEntity) continue;
        if (auto* morph = registry.tryGet<MorphWeights>(e)) {
            const std::uint32_t begin = s.weightOffset[n];
            const std::size_t count = s.weightOffset[n + 1] - begin;
            if (morph->weights.size() == count) {
                std::copy_n(s.weights.begin() + begin, count, morph->weights.begin());
            }
        }
    }
}

}  // namespace

ecs::Mat4 affineInverse(const ecs::Mat4& m) {
    // A mesh at the origin (most skinned meshes): the identity, as the adjugate would give.
    if (isIdentity(m)) return ecs::Mat4::identity();
    const float a = m(0, 0), b = m(0, 1), c = m(0, 2);
    const float d = m(1, 0), e = m(1, 1), f = m(1, 2);
    const float g = m(2, 0), h = m(2, 1), i = m(2, 2);
    const float A = e * i - f * h, B = -(d * i - f * g), C = d * h - e * g;
    const float det = a * A + b * B + c * C;
    if (std::fabs(det) < 1e-30f) return ecs::Mat4::identity();
    const float s = 1.0f / det;
    ecs::Mat4 r;
    r(0, 0) = A * s;
    r(0, 1) = -(b * i - c * h) * s;
    r(0, 2) = (b * f - c * e) * s;
    r(1, 0) = B * s;
    r(1, 1) = (a * i - c * g) * s;
    r(1, 2) = -(a * f - c * d) * s;
    r(2, 0) = C * s;
    r(2, 1) = -(a * h - b * g) * s;
    r(2, 2) = (a * e - b * d) * s;
    const ecs::Vec3 t{m(0, 3), m(1, 3), m(2, 3)};
    for (int row = 0; row < 3; ++row)
        r(row, 3) = -(r(row, 0) * t.x + r(row, 1) * t.y + r(row, 2) * t.z);
    return r;
}

namespace {

// The WorldTransform pool, fetched once per frame (null: no entity has one), and the
// LocalTransform pool (null: none), for the worlds a skeleton pass left unwritten.
struct JointWorlds {
    const ecs::Registry& registry;
    const ecs::ComponentPool* pool;
    const ecs::ComponentPool* locals;

    std::uint32_t indexOf(ecs::Entity e) const {
        return pool && e != ecs::kNullEntity && registry.valid(e) ? pool->indexOf(e)
                                                                  : ecs::ComponentPool::kAbsent;
    }
    ecs::Tick tick(std::uint32_t index) const {
        return index == ecs::ComponentPool::kAbsent ? ecs::kNeverTick : pool->changeTicks()[index];
    }
    const ecs::WorldTransform* world(std::uint32_t index) const {
        return index == ecs::ComponentPool::kAbsent
                   ? nullptr
                   : &pool->typedData<ecs::WorldTransform>()[index];
    }
};

// The world matrix propagation gives `e` (its parent's world, when the parent has both
// transforms, times its local, with propagation's own product), composed from the locals
// up the hierarchy: what a joint whose WorldTransform the skeleton pass left unwritten has.
// An entity without a LocalTransform keeps its stored world (propagation leaves it alone).
ecs::Mat4 worldFromLocals(const JointWorlds& worlds, ecs::Entity e, int depth = 0) {
    const std::uint32_t local = worlds.locals && e != ecs::kNullEntity && worlds.registry.valid(e)
                                    ? worlds.locals->indexOf(e)
                                    : ecs::ComponentPool::kAbsent;
    const std::uint32_t world = worlds.indexOf(e);
    if (local == ecs::ComponentPool::kAbsent || world == ecs::ComponentPool::kAbsent || depth > 256)
        return world == ecs::ComponentPool::kAbsent ? ecs::Mat4::identity()
                                                    : worlds.world(world)->matrix;
    const ecs::Entity parent = ecs::parentOf(worlds.registry, e);
    const bool placed = parent != ecs::kNullEntity && worlds.registry.valid(parent) &&
                        worlds.locals->indexOf(parent) != ecs::ComponentPool::kAbsent &&
                        worlds.indexOf(parent) != ecs::ComponentPool::kAbsent;
    const ecs::Mat4 parentWorld = placed ? worldFromLocals(worlds, parent, depth + 1) : ecs::Mat4{};
    const ecs::LocalTransform& t = worlds.locals->typedData<ecs::LocalTransform>()[local];
    ecs::Mat4 out;
    ecs::composeWorld(placed ? &parentWorld : nullptr, t.position, t.rotation, t.scale, out);
    return out;
}

// The mesh's and joints' dense WorldTransform indices, looked up again only when the pool's
// structure changed (sized once: no allocation after).
void refreshWorldIndices(const JointWorlds& worlds, ecs::Entity entity, Skin& skin) {
    const std::uint32_t version = worlds.pool ? worlds.pool->structureVersion() : 0;
    if (skin.worldPool == worlds.pool && skin.worldVersion == version &&
        skin.jointWorldIndex.size() == skin.joints.size())
        return;
    skin.meshWorldIndex = worlds.indexOf(entity);
    skin.jointWorldIndex.resize(skin.joints.size());
    for (std::size_t j = 0; j < skin.joints.size(); ++j)
        skin.jointWorldIndex[j] = worlds.indexOf(skin.joints[j]);
    skin.worldPool = worlds.pool;
    skin.worldVersion = version;
}

void updateSkin(const JointWorlds& worlds, ecs::Entity entity, Skin& skin) {
    if (skin.model == nullptr || skin.skin < 0) return;
    const SkinData& data = skin.model->skins[static_cast<std::size_t>(skin.skin)];
    // Built this frame by the skeleton pass and no world changed since (the pool's newest
    // change tick is the one the pass built from): the scan below would find every tick at
    // or below builtFrom, so it is skipped (the same outcome, without reading 25 ticks).
    if (skin.builtByPose && skin.builtFrom != ecs::kNeverTick && worlds.pool != nullptr &&
        worlds.pool->latestChange() <= skin.builtFrom &&
        skin.jointMatrices.size() == data.joints.size()) {
        skin.builtByPose = false;
        return;
    }
    refreshWorldIndices(worlds, entity, skin);
    ecs::Tick newest = worlds.tick(skin.meshWorldIndex);
    for (const std::uint32_t index : skin.jointWorldIndex)
        newest = std::max(newest, worlds.tick(index));
    skin.builtByPose = false;
    // (A skeleton pass that left joint worlds unwritten built from newer worlds than their
    // ticks say: nothing newer than builtFrom means current.)
    if (skin.builtFrom != ecs::kNeverTick && newest <= skin.builtFrom &&
        skin.jointMatrices.size() == data.joints.size()) {
        // Built this frame by the skeleton pass from these very worlds, or still: current.
        return;
    }
    // Propagation moved something since (or nothing built them yet): from the worlds.
    skin.builtFrom = newest;
    const ecs::WorldTransform* meshWorld = worlds.world(skin.meshWorldIndex);
    if (skin.worldsSkippedByPose) {
        // Some joints' stored worlds are stale: each from the locals (rare: propagation
        // moved something after the pass, e.g. an attachment's joint or the character).
        const ecs::Mat4 toMesh =
            meshWorld ? affineInverse(worldFromLocals(worlds, entity)) : ecs::Mat4::identity();
        ecs::Mat4 jointWorld;
        buildJointMatrices(skin, data, toMesh, [&](std::size_t j) -> const ecs::Mat4* {
            if (j >= skin.jointWorldIndex.size() ||
                worlds.world(skin.jointWorldIndex[j]) == nullptr)
                return nullptr;
            jointWorld = worldFromLocals(worlds, skin.joints[j]);
            return &jointWorld;
        });
        return;
    }
    const ecs::Mat4 toMesh = meshWorld ? affineInverse(meshWorld->matrix) : ecs::Mat4::identity();
    buildJointMatrices(skin, data, toMesh, [&](std::size_t j) -> const ecs::Mat4* {
        const ecs::WorldTransform* world =
            j < skin.jointWorldIndex.size() ? worlds.world(skin.jointWorldIndex[j]) : nullptr;
        return world ? &world->matrix : nullptr;
    });
}

constexpr std::size_t kPlayersPerJob = 16;  // prefetching runs within a job's range
// Prefetching pays only once the players' state (about 4.5 KB per Fox: scratch, pose, pass
// table, joint matrices) outgrows a core's L2 cache (1 MB here): below this many players the
// data is already in cache and the prefetch calls are pure cost. Measured (Fox crowds,
// candela-bench-animation, five interleaved rounds): without them 6 to 8 % faster at 1 to 100
// Foxes, but 20 % slower at 1,000 and 10 % slower at 10,000.
constexpr std::size_t kPrefetchFromPlayers = 192;
constexpr std::size_t kSkinsPerJob = 16;

// A pool with at least one component, or null.
ecs::ComponentPool* nonEmpty(ecs::ComponentPool* pool) {
    return pool != nullptr && pool->size() > 0 ? pool : nullptr;
}

// Every player in its pool's dense order: the records themselves, by position, with no entity
// lookup per player (the structure stays locked meanwhile, as during a view's walk).
void advanceAll(ecs::Registry& registry, ecs::JobSystem& jobs, ecs::ComponentPool& playerPool,
                float deltaSeconds) {
    const ecs::Registry::StructureLock lock = registry.lockStructure();
    AnimationPlayer* const players = playerPool.typedData<AnimationPlayer>();
    const std::size_t count = playerPool.size();
    TransformPools pools;
    pools.locals = nonEmpty(registry.pool<ecs::LocalTransform>());
    pools.worlds = nonEmpty(registry.pool<ecs::WorldTransform>());
    pools.skins = nonEmpty(registry.pool<Skin>());
    pools.hierarchyVersion = ecs::hierarchyVersion(registry);
    const bool prefetch = count >= kPrefetchFromPlayers;
    jobs.parallelFor(count, kPlayersPerJob, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            if (prefetch) {
                // The next players' data is requested while this one works: the record two
                // ahead (its address only: nothing of it is read), what it points to one
                // ahead, in this job's range only (another job may be writing its players'
                // scratch).
                if (i + 2 < count) prefetchPlayerRecord(players[i + 2]);
                if (i + 1 < end) prefetchSkeletonPose(pools, players[i + 1]);
            }
            advancePlayer(registry, pools, players[i], deltaSeconds);
        }
    });
}

// Every skin in its pool's dense order, as advanceAll walks the players.
void updateAll(ecs::Registry& registry, ecs::JobSystem& jobs, ecs::ComponentPool& skinPool) {
    const ecs::Registry::StructureLock lock = registry.lockStructure();
    Skin* const skins = skinPool.typedData<Skin>();
    const ecs::Entity* const entities = skinPool.entities();
    const JointWorlds worlds{registry, nonEmpty(registry.pool<ecs::WorldTransform>()),
                             nonEmpty(registry.pool<ecs::LocalTransform>())};
    jobs.parallelFor(skinPool.size(), kSkinsPerJob, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
            updateSkin(worlds, entities[i], skins[i]);
    });
}

}  // namespace

void advanceAnimationPlayers(ecs::Registry& registry, ecs::JobSystem& jobs, float deltaSeconds) {
    ecs::ComponentPool* const players = nonEmpty(registry.pool<AnimationPlayer>());
    if (players == nullptr) return;
    // This frame's pose gets a tick of its own: the skeleton pass stamps worlds and skins
    // (Skin::builtFrom) with it, and propagation, which otherwise advances the tick, has
    // nothing to do for joints the pass wrote.
    registry.advanceTick();
    advanceAll(registry, jobs, *players, deltaSeconds);
}

void updateSkins(ecs::Registry& registry, ecs::JobSystem& jobs) {
    ecs::ComponentPool* const skins = nonEmpty(registry.pool<Skin>());
    if (skins == nullptr) return;
    updateAll(registry, jobs, *skins);
}

void addAnimationSystems(ecs::Scheduler& scheduler, std::function<float()> deltaSeconds) {
    scheduler
        .addSystem("sample animation", ecs::Phase::Update,
                   [deltaSeconds](ecs::SystemContext& ctx) {
                       advanceAnimationPlayers(ctx.registry(), ctx.jobs(), deltaSeconds());
                   })
        .reads<ecs::HierarchyNode>()
        .writes<AnimationPlayer, ecs::LocalTransform, ecs::WorldTransform, MorphWeights, Skin>();
    scheduler
        .addSystem("joint matrices", ecs::Phase::PostUpdate,
                   [](ecs::SystemContext& ctx) { updateSkins(ctx.registry(), ctx.jobs()); })
        .reads<ecs::WorldTransform>()
        .writes<Skin>();
}

std::vector<std::array<float, 6>> jointBoundsOf(const Mesh& mesh, std::size_t jointCount) {
    constexpr float kInf = std::numeric_limits<float>::infinity();
    std::vector<std::array<float, 6>> bounds(jointCount, {kInf, kInf, kInf, -kInf, -kInf, -kInf});
    for (const Primitive& p : mesh.primitives) {
        for (std::size_t v = 0; v < p.joints.size(); ++v) {
            for (int c = 0; c < 4; ++c) {
                if (!(p.weights[v][c] > 0)) continue;
                const std::uint16_t j = p.joints[v][c];
                if (j >= bounds.size()) continue;
                // Morph targets can push vertices out: grow by every target's delta.
                Float3 lo = p.positions[v], hi = p.positions[v];
                for (const MorphTarget& t : p.morphTargets) {
                    if (t.positionDeltas.empty()) continue;
                    for (int a = 0; a < 3; ++a) {
                        lo[a] += std::min(0.0f, t.positionDeltas[v][a]);
                        hi[a] += std::max(0.0f, t.positionDeltas[v][a]);
                    }
                }
                std::array<float, 6>& box = bounds[j];
                for (int a = 0; a < 3; ++a) {
                    box[a] = std::min(box[a], lo[a]);
                    box[a + 3] = std::max(box[a + 3], hi[a]);
                }
            }
        }
    }
    // Stored as centre and half size, what each frame's bounds need (computed here once, the
    // same floats the frame would compute); a joint that moves no vertex gets half size -inf.
    for (std::array<float, 6>& box : bounds) {
        const std::array<float, 6> minMax = box;
        for (int a = 0; a < 3; ++a) {
            box[a] = 0.5f * (minMax[a] + minMax[a + 3]);
            box[a + 3] = 0.5f * (minMax[a + 3] - minMax[a]);
        }
    }
    return bounds;
}

void computeJointBounds(const Model& model, std::int32_t meshIndex, Skin& skin) {
    const SkinData& data = model.skins[static_cast<std::size_t>(skin.skin)];
    const Mesh& mesh = model.meshes[static_cast<std::size_t>(meshIndex)];
    if (mesh.jointBounds.size() >= data.joints.size()) {
        // Not owned: the model outlives its entities (as for the clips).
        skin.jointBounds = std::shared_ptr<const std::vector<std::array<float, 6>>>(
            std::shared_ptr<const void>(), &mesh.jointBounds);
        return;
    }
    skin.jointBounds = std::make_shared<const std::vector<std::array<float, 6>>>(
        jointBoundsOf(mesh, data.joints.size()));
}

}  // namespace candela::content
