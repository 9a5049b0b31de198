#include "skeleton_pose_pass.h"

#include <algorithm>

#include "candela/content/model.h"
#include "candela/ecs/affine_multiply.h"
#include "candela/ecs/hierarchy.h"
#include "joint_matrices.h"

namespace candela::content {
namespace {

constexpr std::uint32_t kAbsent = ecs::ComponentPool::kAbsent;
// Skeletons up to this many pass nodes keep the frame's world matrices in a per-thread
// buffer (4 KB).
constexpr std::size_t kThreadPassNodes = 64;

std::uint32_t indexIn(const ecs::ComponentPool* pool, const ecs::Registry& registry,
                      ecs::Entity e) {
    return pool && e != ecs::kNullEntity && registry.valid(e) ? pool->indexOf(e) : kAbsent;
}

bool bindingIsCurrent(const TransformPools& pools, const AnimationPlayer& player) {
    const AnimationPlayer::Scratch& s = player.scratch;
    return s.bound && s.localPool == pools.locals && s.worldPool == pools.worlds &&
           (!pools.locals || pools.locals->structureVersion() == s.localVersion) &&
           (!pools.worlds || pools.worlds->structureVersion() == s.worldVersion) &&
           pools.hierarchyVersion == s.hierarchyVersion &&
           s.writeJointWorlds == player.writeJointWorlds;
}

// Is `e`'s Skin the one instantiateModel gave mesh node `node`, with the node entities as
// its joints (what the pass builds from)?
bool skinMatchesModel(const ecs::Registry& registry, const AnimationPlayer& player,
                      std::size_t node, ecs::Entity e) {
    const Model& model = *player.model;
    const Skin* skin = registry.tryGet<Skin>(e);
    if (skin == nullptr || skin->model != &model || skin->skin != model.nodes[node].skin)
        return false;
    const SkinData& data = model.skins[static_cast<std::size_t>(skin->skin)];
    if (skin->joints.size() != data.joints.size()) return false;
    for (std::size_t j = 0; j < data.joints.size(); ++j) {
        const auto jointNode = static_cast<std::size_t>(data.joints[j]);
        const ecs::Entity expected = jointNode < player.nodeEntities.size()
                                         ? player.nodeEntities[jointNode]
                                         : ecs::kNullEntity;
        if (skin->joints[j] != expected) return false;
    }
    return true;
}

// Sizes and fills the pass's per-node tables (sizes are kept: rebinding allocates nothing).
void bind(const ecs::Registry& registry, const TransformPools& pools, AnimationPlayer& player) {
    const Model& model = *player.model;
    AnimationPlayer::Scratch& s = player.scratch;
    const std::size_t count = model.nodes.size();
    s.parentWorld.assign(count, kAbsent);
    s.localIndex.assign(count, kAbsent);
    s.worldIndex.assign(count, kAbsent);
    s.stampLocal.assign(count, 1);
    s.order.clear();
    s.order.reserve(count);
    s.skins.clear();
    s.skins.reserve(count);
    s.skinPool = nullptr;  // refreshSkinIndices looks the skins up again
    s.direct = true;

    // Parents first: the roots, then each listed node's children (explicit queue, the order
    // vector itself).
    for (std::size_t n = 0; n < count; ++n)
        if (model.nodes[n].parent == kNoIndex) s.order.push_back(static_cast<std::uint32_t>(n));
    for (std::size_t i = 0; i < s.order.size() && s.order.size() <= count; ++i)
        for (std::int32_t child : model.nodes[s.order[i]].children)
            s.order.push_back(static_cast<std::uint32_t>(child));
    if (s.order.size() != count) s.direct = false;  // not a forest (the loader rejects that)
    // PassNode keeps the model node in 16 bits.
    if (count > AnimationPlayer::Scratch::kMaxPassModelNodes) s.direct = false;

    // Joints whose only reader is a skin.
    std::vector<std::uint8_t>& isJoint = s.stampLocal;  // reused below: 0 = joint, for now
    for (const SkinData& skin : model.skins)
        for (std::int32_t joint : skin.joints)
            isJoint[static_cast<std::size_t>(joint)] = 0;

    auto entityOf = [&](std::int32_t node) {
        return node >= 0 && static_cast<std::size_t>(node) < player.nodeEntities.size()
                   ? player.nodeEntities[static_cast<std::size_t>(node)]
                   : ecs::kNullEntity;
    };
    for (std::size_t n = 0; n < count && s.direct; ++n) {
        const Node& node = model.nodes[n];
        const ecs::Entity e = entityOf(static_cast<std::int32_t>(n));
        if (e == ecs::kNullEntity || !registry.valid(e)) continue;
        s.localIndex[n] = indexIn(pools.locals, registry, e);
        s.worldIndex[n] = indexIn(pools.worlds, registry, e);
        // Propagation computes a node from its entity's parent: the pass must see the same
        // parent, and both transforms (a half-transformed node is propagation's business).
        if ((s.localIndex[n] == kAbsent) != (s.worldIndex[n] == kAbsent)) s.direct = false;
        const ecs::Entity entityParent = ecs::parentOf(registry, e);
        const ecs::Entity modelParent = entityOf(node.parent);
        if (modelParent != ecs::kNullEntity && entityParent != modelParent) s.direct = false;
        // Propagation places a node under its entity parent only when that has both
        // transforms.
        if (indexIn(pools.locals, registry, entityParent) != kAbsent)
            s.parentWorld[n] = indexIn(pools.worlds, registry, entityParent);
        std::uint32_t modelChildren = 0;
        for (std::int32_t child : node.children)
            if (entityOf(child) != ecs::kNullEntity) ++modelChildren;
        const auto* links = registry.tryGet<ecs::HierarchyNode>(e);
        const std::uint32_t entityChildren = links ? links->childCount : 0;
        const bool onlySkinsRead = isJoint[n] == 0 && node.mesh == kNoIndex &&
                                   node.camera == kNoIndex && node.light == kNoIndex &&
                                   entityChildren == modelChildren;
        s.stampLocal[n] = onlySkinsRead ? 0 : 1;
        if (node.mesh != kNoIndex && node.skin != kNoIndex &&
            skinMatchesModel(registry, player, n, e))
            s.skins.push_back({static_cast<std::uint32_t>(n), kAbsent, kAbsent, 0, 0, 0});
    }
    s.passNodes.clear();
    s.passNodes.reserve(count);
    s.passOfNode.assign(count, kAbsent);
    s.skipsWorlds = false;
    using Scratch = AnimationPlayer::Scratch;
    for (const std::uint32_t n : s.order) {
        if (s.localIndex[n] == kAbsent) continue;  // no entity: nothing reads it
        std::uint32_t parentPass = kAbsent;
        for (std::size_t i = 0; i < s.passNodes.size(); ++i)
            if (s.parentWorld[n] != kAbsent && s.passNodes[i].world == s.parentWorld[n])
                parentPass = static_cast<std::uint32_t>(i);
        const bool writeWorld = s.stampLocal[n] != 0 || player.writeJointWorlds;
        s.skipsWorlds = s.skipsWorlds || !writeWorld;
        s.passOfNode[n] = static_cast<std::uint32_t>(s.passNodes.size());
        const auto flags =
            static_cast<std::uint8_t>((s.stampLocal[n] != 0 ? Scratch::kPassStampLocal : 0) |
                                      (writeWorld ? Scratch::kPassWriteWorld : 0) |
                                      (parentPass != kAbsent ? Scratch::kPassParentInPass : 0));
        s.passNodes.push_back({s.localIndex[n], s.worldIndex[n],
                               parentPass != kAbsent ? parentPass : s.parentWorld[n],
                               static_cast<std::uint16_t>(n), flags});
    }
    s.skinJointPass.clear();
    for (AnimationPlayer::Scratch::SkinBinding& binding : s.skins) {
        const SkinData& skin =
            model.skins[static_cast<std::size_t>(model.nodes[binding.meshNode].skin)];
        binding.meshPass = s.passOfNode[binding.meshNode];
        binding.jointBegin = static_cast<std::uint32_t>(s.skinJointPass.size());
        bool affine = true;
        for (std::size_t j = 0; j < skin.joints.size(); ++j) {
            s.skinJointPass.push_back(s.passOfNode[static_cast<std::size_t>(skin.joints[j])]);
            affine = affine && isAffine(skin.inverseBindMatrices[j]);
        }
        binding.jointEnd = static_cast<std::uint32_t>(s.skinJointPass.size());
        binding.affine = affine ? 1 : 0;
    }
    s.passWorlds.resize(s.passNodes.size() > kThreadPassNodes ? s.passNodes.size() : 0);
    s.writeJointWorlds = player.writeJointWorlds;
    s.worldsToPrefetchCount = 0;
    for (const AnimationPlayer::Scratch::PassNode& p : s.passNodes)
        if ((p.flags & Scratch::kPassWriteWorld) &&
            s.worldsToPrefetchCount < s.worldsToPrefetch.size())
            s.worldsToPrefetch[s.worldsToPrefetchCount++] = p.world;
    s.passMoved.assign(s.passNodes.size() > kThreadPassNodes ? s.passNodes.size() : 0, 0);
    s.worldFirst = kAbsent;
    s.worldEnd = 0;
    for (const AnimationPlayer::Scratch::PassNode& p : s.passNodes) {
        s.worldFirst = std::min(s.worldFirst, p.world);
        s.worldEnd = std::max(s.worldEnd, p.world + 1);
    }
    s.localPool = pools.locals;
    s.worldPool = pools.worlds;
    s.localVersion = pools.locals ? pools.locals->structureVersion() : 0;
    s.worldVersion = pools.worlds ? pools.worlds->structureVersion() : 0;
    s.hierarchyVersion = pools.hierarchyVersion;
    s.bound = true;
}

// The classic path: stamped locals for the animated nodes, nothing else.
void writeLocalsOnly(ecs::Registry& registry, const TransformPools& pools, AnimationPlayer& player,
                     const std::uint8_t* touched) {
    const AnimationPlayer::Scratch& s = player.scratch;
    if (pools.locals == nullptr) return;
    auto* locals = pools.locals->typedData<ecs::LocalTransform>();
    const ecs::Tick now = registry.currentTick();
    for (std::size_t n = 0; n < s.pose.size() && n < player.nodeEntities.size(); ++n) {
        if (!(touched[n] & kTransformTouched)) continue;
        const std::uint32_t index = indexIn(pools.locals, registry, player.nodeEntities[n]);
        if (index == kAbsent) continue;
        locals[index] = s.pose[n];
        pools.locals->stamp(index, now);
    }
}

// The dense Skin-pool indices of the player's skin nodes, refreshed when the pool changed
// structure (bind resets skinPool, so a new binding is looked up too).
void refreshSkinIndices(const ecs::Registry& registry, const TransformPools& pools,
                        AnimationPlayer::Scratch& s, const AnimationPlayer& player) {
    const std::uint32_t version = pools.skins ? pools.skins->structureVersion() : 0;
    if (s.skinPool == pools.skins && s.skinVersion == version) return;
    for (AnimationPlayer::Scratch::SkinBinding& binding : s.skins)
        binding.skinIndex = indexIn(pools.skins, registry, player.nodeEntities[binding.meshNode]);
    s.skinPool = pools.skins;
    s.skinVersion = version;
}

// `passWorlds`: this frame's world matrix per pass node.
void buildSkin(AnimationPlayer& player, const TransformPools& pools, const ecs::Mat4* passWorlds,
               std::size_t k, ecs::Tick now) {
    const Model& model = *player.model;
    const AnimationPlayer::Scratch& s = player.scratch;
    const AnimationPlayer::Scratch::SkinBinding& binding = s.skins[k];
    if (pools.skins == nullptr || binding.skinIndex == kAbsent) return;
    if (binding.meshPass == kAbsent) return;  // a mesh without transforms: not built
    Skin* skin = pools.skins->typedData<Skin>() + binding.skinIndex;
    const SkinData& data = model.skins[static_cast<std::size_t>(skin->skin)];
    const ecs::Mat4 toMesh = affineInverse(passWorlds[binding.meshPass]);
    const std::uint32_t* jointPass = s.skinJointPass.data() + binding.jointBegin;
    if (skin->skin != model.nodes[binding.meshNode].skin ||
        data.joints.size() != binding.jointEnd - binding.jointBegin) {
        // The Skin changed since bind (game code): its joints looked up one by one.
        buildJointMatrices(*skin, data, toMesh, [&](std::size_t j) -> const ecs::Mat4* {
            const auto node = static_cast<std::size_t>(data.joints[j]);
            return s.passOfNode[node] == kAbsent ? nullptr : &passWorlds[s.passOfNode[node]];
        });
    } else {
        buildJointMatrices(
            *skin, data, toMesh,
            [&](std::size_t j) -> const ecs::Mat4* {
                return jointPass[j] == kAbsent ? nullptr : &passWorlds[jointPass[j]];
            },
            binding.affine != 0);
    }
    skin->worldsSkippedByPose = s.skipsWorlds;
    skin->builtFrom = now;
    skin->builtByPose = true;
}

// One prefetch per 64-byte cache line that [begin, begin + bytes) touches.
void prefetchBytes(const void* begin, std::size_t bytes, bool forWriting) {
    constexpr std::uintptr_t kLine = 64;
    const auto first = reinterpret_cast<std::uintptr_t>(begin) & ~(kLine - 1);
    const auto end = reinterpret_cast<std::uintptr_t>(begin) + bytes;
    for (std::uintptr_t line = first; line < end; line += kLine) {
        const auto* p = reinterpret_cast<const void*>(line);
        if (forWriting) {
            __builtin_prefetch(p, 1);
        } else {
            __builtin_prefetch(p, 0);
        }
    }
}

template <class T>
void prefetchVector(const std::vector<T>& v, bool forWriting) {
    prefetchBytes(v.data(), v.size() * sizeof(T), forWriting);
}

}  // namespace

void prefetchSkeletonPose(const TransformPools& pools, const AnimationPlayer& player) {
    const AnimationPlayer::Scratch& s = player.scratch;
    if (!s.bound || !s.direct || pools.locals == nullptr || pools.worlds == nullptr) return;
    prefetchVector(s.cursors, true);
    // A bound direct player samples into its entities' locals (through localIndex), not
    // into its scratch pose (a crossfade still does).
    if (s.direct) {
        prefetchVector(s.localIndex, false);
    } else {
        prefetchVector(s.pose, true);
    }
    prefetchVector(s.passNodes, false);
    if (pools.skins != nullptr && s.skinPool == pools.skins &&
        s.skinVersion == pools.skins->structureVersion()) {
        for (const AnimationPlayer::Scratch::SkinBinding& binding : s.skins)
            if (binding.skinIndex != kAbsent)
                prefetchBytes(pools.skins->typedData<Skin>() + binding.skinIndex, sizeof(Skin),
                              true);
    }
    // Not the entities' locals: propagation lays skeletons out depth-first, one after another,
    // so players' locals form one sequential stream the hardware prefetcher follows, and
    // prefetching them too only spent miss buffers (measured: 3 % slower at 1,000 and 10,000
    // Foxes). Ranges a skeleton keeps compact; a scattered one is left alone.
    constexpr std::uint32_t kMaxSpan = 4 * 64;
    // Worlds: the whole range where the pass writes them all, else the few it writes (a
    // skeleton whose joints only skins read writes its root's and its meshes').
    if (s.skipsWorlds) {
        for (std::uint32_t k = 0; k < s.worldsToPrefetchCount; ++k) {
            prefetchBytes(pools.worlds->typedData<ecs::WorldTransform>() + s.worldsToPrefetch[k],
                          sizeof(ecs::WorldTransform), true);
            prefetchBytes(pools.worlds->changeTicks() + s.worldsToPrefetch[k], sizeof(ecs::Tick),
                          true);
        }
    }
    if (!s.skipsWorlds && s.worldFirst < s.worldEnd && s.worldEnd - s.worldFirst <= kMaxSpan) {
        prefetchBytes(pools.worlds->typedData<ecs::WorldTransform>() + s.worldFirst,
                      (s.worldEnd - s.worldFirst) * sizeof(ecs::WorldTransform), true);
        prefetchBytes(pools.worlds->changeTicks() + s.worldFirst,
                      (s.worldEnd - s.worldFirst) * sizeof(ecs::Tick), true);
    }
}

void prefetchPlayerRecord(const AnimationPlayer& player) {
    prefetchBytes(&player, sizeof(AnimationPlayer), false);
}

bool prepareSkeletonPose(ecs::Registry& registry, const TransformPools& pools,
                         AnimationPlayer& player) {
    if (!bindingIsCurrent(pools, player)) bind(registry, pools, player);
    return player.scratch.direct && pools.locals != nullptr && pools.worlds != nullptr;
}

void writeSkeletonPose(ecs::Registry& registry, const TransformPools& pools,
                       AnimationPlayer& player, const std::uint8_t* touched, bool poseInLocals) {
    AnimationPlayer::Scratch& s = player.scratch;
    // poseInLocals: the caller's prepareSkeletonPose returned true this frame (bound, direct).
    if (!poseInLocals && !prepareSkeletonPose(registry, pools, player)) {
        writeLocalsOnly(registry, pools, player, touched);
        return;
    }
    auto* locals = pools.locals->typedData<ecs::LocalTransform>();
    auto* worlds = pools.worlds->typedData<ecs::WorldTransform>();
    ecs::Tick* worldTicks = pools.worlds->changeTicks();
    const ecs::Tick now = registry.currentTick();
    // Each pass node's world this frame, in L1 for the children and the skins: the thread's
    // buffer for a skeleton of usual size (statically initialised, reused by every player
    // the thread runs), else the player's own (sized by bind).
    // The same for whether each node's world moved (read by its children only).
    alignas(64) thread_local ecs::Mat4 threadWorlds[kThreadPassNodes];
    thread_local std::uint8_t threadMoved[kThreadPassNodes];
    const bool threadBuffers = s.passNodes.size() <= kThreadPassNodes;
    ecs::Mat4* passWorlds = threadBuffers ? threadWorlds : s.passWorlds.data();
    std::uint8_t* const passMoved = threadBuffers ? threadMoved : s.passMoved.data();
    // Held in locals: the SIMD stores below may alias anything, so the vectors' sizes and
    // pointers read through `s` would be reloaded every node.
    const AnimationPlayer::Scratch::PassNode* const passNodes = s.passNodes.data();
    const std::size_t passCount = s.passNodes.size();
    const ecs::LocalTransform* const scratchPose = s.pose.data();
    for (std::size_t i = 0; i < passCount; ++i) {
        const AnimationPlayer::Scratch::PassNode& p = passNodes[i];
        const bool animated = (touched[p.node] & kTransformTouched) != 0;
        if (animated) {
            if (!poseInLocals) locals[p.local] = scratchPose[p.node];
            if (p.flags & AnimationPlayer::Scratch::kPassStampLocal)
                pools.locals->stamp(p.local, now);
        }
        // Not animated: the entity's own (a game may move it).
        const ecs::LocalTransform& pose = locals[p.local];
        // A node neither animated nor under one that moved keeps its world (and its change
        // tick: readers that track moved entities see only what moved). A node whose world
        // the pass does not write is computed every frame: its entity's may be stale.
        const bool writeWorld = (p.flags & AnimationPlayer::Scratch::kPassWriteWorld) != 0;
        const bool parentInPass = (p.flags & AnimationPlayer::Scratch::kPassParentInPass) != 0;
        const bool moved = animated || !writeWorld || (parentInPass && passMoved[p.parent]);
        passMoved[i] = moved ? 1 : 0;
        if (!moved) {
            passWorlds[i] = worlds[p.world].matrix;
            continue;
        }
        // Local-to-world with propagation's own product, so the worlds it would compute
        // are bit for bit these. Parents come first: theirs are already computed.
        const ecs::Mat4* parent = parentInPass          ? &passWorlds[p.parent]
                                  : p.parent != kAbsent ? &worlds[p.parent].matrix
                                                        : nullptr;
        ecs::composeWorld(parent, pose.position, pose.rotation, pose.scale, passWorlds[i]);
        if (!writeWorld) continue;
        worlds[p.world].matrix = passWorlds[i];
        worldTicks[p.world] = now;
    }
    pools.worlds->noteChange(now);
    refreshSkinIndices(registry, pools, s, player);
    for (std::size_t k = 0; k < s.skins.size(); ++k)
        buildSkin(player, pools, passWorlds, k, now);
}

}  // namespace candela::content
