#pragma once
// Animation components, filled by instantiateModel() for glTF models that have them:
//  - AnimationPlayer (on the model's first root entity): which clip plays, its time, speed,
//    looping, and a crossfade to another clip; it drives the node entities in nodeEntities;
//  - Skin (on each skinned mesh's entity): its joint entities and the joint matrices the
//    renderer skins with, rebuilt after transform propagation;
//  - MorphWeights (on each mesh entity with morph targets): the current target weights.
// The systems that update them are in animation_systems.h.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "candela/ecs/entity.h"
#include "candela/ecs/tick.h"
#include "candela/ecs/transform.h"

namespace candela::content {

struct Model;

struct AnimationPlayer {
    const Model* model = nullptr;  // owns the clips; must outlive the entity
    std::int32_t clip = -1;        // into Model::animations; -1 plays nothing
    float time = 0;                // seconds into `clip` (wrapped or clamped when sampled)
    float speed = 1;               // 1 is real time; negative plays backwards
    bool loop = true;
    bool playing = true;  // false: time stands still, the pose at `time` is still applied
    // Crossfade: while nextClip >= 0, `clip` blends into nextClip over fadeDuration seconds;
    // when the fade ends nextClip becomes `clip` (with its time).
    std::int32_t nextClip = -1;
    float nextTime = 0;
    float fadeDuration = 0;
    float fadeElapsed = 0;

    std::vector<ecs::Entity> nodeEntities;  // model node index -> entity (kNullEntity: not shown)

    // Whether the skeleton pass writes the WorldTransform of joints that only skins read
    // (no mesh, light or camera on them, nothing attached under them). false (the default):
    // it computes their model-space matrices in a buffer of its own, builds the skins from
    // them and writes only their LocalTransform, as an animation runtime keeps its pose
    // out of the scene graph: each Fox stops writing 1.7 KB of world matrices and change
    // ticks per frame. Their WorldTransform is then brought up to date only when something
    // makes propagation recompute them, so code that reads a bare joint's world matrix
    // (without attaching an entity to it, which is detected) sets this to true. Anything
    // attached under a joint, and every mesh, light and camera, is written either way.
    bool writeJointWorlds = false;

    // Starts `clipIndex` from time 0, cancelling any crossfade.
    void play(std::int32_t clipIndex, bool looping = true);
    // Blends from the current clip to `clipIndex` over `seconds` (0: switch at once).
    void crossfade(std::int32_t clipIndex, float seconds);
    // Index of the clip named `name`, or -1.
    std::int32_t findClip(std::string_view name) const;
    // Plays the clip named `nameOrIndex` (a name first, else a decimal index), looping;
    // returns an empty string, or the problem listing the clips there are.
    std::string playByNameOrIndex(const std::string& nameOrIndex);
    // How far the crossfade has gone, 0 (all `clip`) to 1 (all nextClip).
    float fadeWeight() const;

    // Scratch sized once by the sampling system (no per-frame allocation once warm).
    struct Scratch {
        std::vector<ecs::LocalTransform> pose;       // per node, clip A
        std::vector<ecs::LocalTransform> blendPose;  // per node, clip B
        std::vector<float> weights;                  // per node's morph targets, clip A
        std::vector<float> blendWeights;             // clip B
        // The model's rest pose and morph weights, laid out as pose / weights: each frame
        // starts from a copy of them.
        std::vector<ecs::LocalTransform> restPose;
        std::vector<float> restWeights;
        std::vector<std::uint32_t> weightOffset;  // node -> first slot in weights
        std::vector<std::uint8_t> touched;  // node animated by A (1), B (2); large models only
        // Per channel of clip A / B, the key interval sampled last (sampleAnimation's cursor):
        // sized for the model's largest clip, so switching clips allocates nothing.
        std::vector<std::uint32_t> cursors;
        std::vector<std::uint32_t> blendCursors;
        // The skeleton pass (skeleton_pose_pass.cpp), bound to the registry once and again
        // only when a transform pool or the hierarchy changes structure. Per model node: its
        // entity's dense index in the LocalTransform and WorldTransform pools (kAbsent: none),
        // its entity parent's WorldTransform index (kAbsent: a root for propagation), and
        // whether its LocalTransform changes are stamped (1: something besides a skin reads
        // the node: a mesh, light or camera on it, no joint, or an entity attached under it).
        // `order` lists the nodes parents first.
        std::vector<std::uint32_t> order;
        std::vector<std::uint32_t> localIndex;
        std::vector<std::uint32_t> worldIndex;
        std::vector<std::uint32_t> parentWorld;
        std::vector<std::uint8_t> stampLocal;
        // The same, packed in `order` for the frame loop (one contiguous walk).
        // 16 bytes, so a Fox's table spans 7 cache lines rather than 10 (at 10,000 players
        // each line a player touches is a miss).
        struct PassNode {
            std::uint32_t local;
            std::uint32_t world;
            // With kPassParentInPass: the parent's position in passNodes; otherwise its
            // entity parent's WorldTransform index (kAbsent: a root for propagation).
            std::uint32_t parent;
            std::uint16_t node;  // model node (a model of more nodes takes the classic path)
            std::uint8_t flags;  // kPassStampLocal | kPassWriteWorld | kPassParentInPass
            std::uint8_t unused = 0;
        };
        // PassNode::flags. kPassWriteWorld unset: a joint only skins read whose
        // WorldTransform the pass leaves as it was (the skins get its model-space matrix from
        // the pass's own buffer); see AnimationPlayer::writeJointWorlds.
        static constexpr std::uint8_t kPassStampLocal = 1;
        static constexpr std::uint8_t kPassWriteWorld = 2;
        static constexpr std::uint8_t kPassParentInPass = 4;
        static constexpr std::size_t kMaxPassModelNodes = 65535;
        std::vector<PassNode> passNodes;
        std::vector<std::uint32_t> passOfNode;  // model node -> position in passNodes, or kAbsent
        // This frame's world matrices per pass node, for skeletons larger than the pass's
        // stack buffer (sized by bind).
        std::vector<ecs::Mat4> passWorlds;
        bool writeJointWorlds = false;  // the flag bind saw
        bool skipsWorlds = false;       // some pass node has writeWorld 0
        // Where skipsWorlds: the first few WorldTransform indices the pass reads or writes
        // (the model's roots, its meshes), kept in the record for the prefetch.
        std::array<std::uint32_t, 4> worldsToPrefetch{};
        std::uint32_t worldsToPrefetchCount = 0;
        // Per pass node: its world was written this frame (only for skeletons larger than
        // the pass's per-thread buffer, like passWorlds).
        std::vector<std::uint8_t> passMoved;
        // Per mesh node whose Skin this player builds, in one record (one block the pass
        // reads, rather than five): filled by bind, so the pass neither looks a joint up nor
        // tests its matrix each frame.
        struct SkinBinding {
            std::uint32_t meshNode;
            std::uint32_t meshPass;  // the mesh node's position in passNodes, or kAbsent
            // Its entity's dense index in the Skin pool, looked up again only when that pool
            // changes structure (the pass reads the Skin without a sparse lookup).
            std::uint32_t skinIndex;
            // Its skin's joints' positions in passNodes (kAbsent: not in the pass) at
            // [jointBegin, jointEnd) of skinJointPass.
            std::uint32_t jointBegin, jointEnd;
            std::uint32_t affine;  // 1: every inverse bind matrix of its skin is affine
        };
        std::vector<SkinBinding> skins;
        std::vector<std::uint32_t> skinJointPass;
        const void* skinPool = nullptr;
        std::uint32_t skinVersion = 0;
        // The dense index range [first, end) the pass writes in the WorldTransform pool
        // (bind's), so the player before this one can prefetch it.
        std::uint32_t worldFirst = 0, worldEnd = 0;
        const void* localPool = nullptr;
        const void* worldPool = nullptr;
        std::uint32_t localVersion = 0;
        std::uint32_t worldVersion = 0;
        std::uint64_t hierarchyVersion = 0;
        bool bound = false;
        // The entities mirror the model's hierarchy: the pass writes their world transforms
        // and builds the skins itself. Otherwise it only writes local transforms (stamped) and
        // leaves the rest to propagation and updateSkins.
        bool direct = false;
        // The pose last written: a paused player whose clip and time did not change writes
        // nothing (and so its skeleton's skins are not rebuilt).
        bool applied = false;
        std::int32_t appliedClip = -1;
        float appliedTime = 0;
    } scratch;
};

struct Skin {
    const Model* model = nullptr;
    std::int32_t skin = -1;           // into Model::skins
    std::vector<ecs::Entity> joints;  // one per skin joint (kNullEntity: not shown, identity)
    // Per joint: inverse(mesh world) * joint world * inverse bind matrix, i.e. bind-pose mesh
    // space to current mesh space. The renderer skins with these. Only this frame's: motion
    // vectors come from last frame's deformed vertices, which the renderer keeps on the GPU
    // (render/README.md "Animation"), so a second CPU copy would only double what a crowd
    // writes into cache.
    std::vector<ecs::Mat4> jointMatrices;
    // Per joint, the bind-space box of the vertices it influences, as its centre xyz and half
    // size xyz (half size -inf when it influences none): the deformed mesh lies inside the
    // union of these boxes moved by the joint matrices.
    // Shared by every instance of the mesh (Mesh::jointBounds; not owned) or this skin's own.
    std::shared_ptr<const std::vector<std::array<float, 6>>> jointBounds;
    // The deformed mesh's bounds in mesh space (what culling and clusters use).
    ecs::Vec3 boundsMin{}, boundsMax{};
    bool boundsValid = false;
    // The newest WorldTransform change (mesh or joints) the matrices were built from: a skin
    // whose skeleton did not move is skipped (a still character costs a few tick reads).
    ecs::Tick builtFrom = ecs::kNeverTick;
    // Built this frame by its player's skeleton pass from the worlds it wrote (stamped
    // builtFrom): updateSkins keeps the matrices unless propagation changed a joint since.
    bool builtByPose = false;
    // The skeleton pass that last built the matrices leaves some joints' WorldTransform
    // unwritten (AnimationPlayer::writeJointWorlds; their LocalTransform is current):
    // updateSkins then composes joint worlds from the locals up the hierarchy, as
    // propagation would, instead of reading them.
    bool worldsSkippedByPose = false;
    // Dense indices of the mesh's and joints' WorldTransform, valid while the pool's structure
    // is unchanged (updateSkins' change-tick scan reads them instead of looking entities up).
    std::uint32_t meshWorldIndex = 0xFFFFFFFFu;
    std::vector<std::uint32_t> jointWorldIndex;
    const void* worldPool = nullptr;
    std::uint32_t worldVersion = 0;
};

struct MorphWeights {
    // One per morph target of the mesh (this frame's; last frame's morphing stays in the
    // renderer's previous deformed vertices, as for Skin::jointMatrices).
    std::vector<float> weights;
};

}  // namespace candela::content
