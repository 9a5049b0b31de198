#pragma once
// A glTF 2.0 asset as plain CPU data: what loadGltf() produces, what the asset cache keeps and
// what scene instantiation turns into entities. Indices between arrays are int32 with -1 for
// "none", exactly as glTF writes them, so they can be checked and printed.
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "candela/content/animation.h"
#include "candela/content/components/camera.h"
#include "candela/content/components/collider.h"
#include "candela/content/components/light.h"
#include "candela/content/components/rigid_body.h"
#include "candela/content/hair.h"
#include "candela/content/image.h"
#include "candela/content/material.h"
#include "candela/content/wire.h"

namespace candela::content {

inline constexpr std::int32_t kNoIndex = -1;

using Float2 = std::array<float, 2>;
using Float3 = std::array<float, 3>;
using Float4 = std::array<float, 4>;

// One morph target's per-vertex offsets; a stream is empty when the target does not move it.
struct MorphTarget {
    std::vector<Float3> positionDeltas;
    std::vector<Float3> normalDeltas;
    std::vector<Float3> tangentDeltas;  // xyz only; w (handedness) never morphs
};

using JointIndices = std::array<std::uint16_t, 4>;

// Structure-of-arrays vertex data for one triangle list. Optional streams are empty when absent.
struct Primitive {
    std::vector<Float3> positions;
    std::vector<Float3> normals;   // always filled (generated flat when the file has none)
    std::vector<Float4> tangents;  // xyz unit tangent, w = bitangent sign; filled when generated
    std::vector<Float2> uv0;
    std::vector<Float2> uv1;
    std::vector<Float4> colors;          // linear RGBA; COLOR_0 with RGB gets alpha 1
    std::vector<std::uint32_t> indices;  // triangle list, every index < positions.size()
    // Skinning: the four largest influences over all JOINTS_n/WEIGHTS_n sets, weights summing
    // to 1. Both empty when the primitive is not skinned.
    std::vector<JointIndices> joints;
    std::vector<Float4> weights;
    std::vector<MorphTarget> morphTargets;
    std::int32_t material = kNoIndex;  // kNoIndex: the glTF default material
    Float3 boundsMin{0, 0, 0};
    Float3 boundsMax{0, 0, 0};
    bool normalsGenerated = false;
    bool tangentsGenerated = false;
};

struct Mesh {
    std::string name;
    std::vector<Primitive> primitives;  // primitives that failed to load are left out
    std::vector<Wire> wires;            // line primitives whose material has a wireRadius
    std::vector<Hair> hair;             // line primitives whose material has extras.hair
    // Morph target weights when no node or animation sets them; one per target (all
    // primitives of a mesh have the same target count, or none of them keeps targets).
    std::vector<float> defaultWeights;
    // For a mesh a skin deforms: per joint index its JOINTS_n attributes use (as many as the
    // largest skin that deforms it has joints), the bind-space box of the vertices that joint
    // moves, grown by every morph target's deltas, as centre xyz and half size xyz (half size
    // -inf: it moves none). Filled by the loader (jointBoundsOf), shared by every instance.
    std::vector<std::array<float, 6>> jointBounds;
};

struct Texture {
    std::string name;
    std::int32_t image = kNoIndex;  // into Model::images; always valid after loading
    Sampler sampler;
};

struct Transform {
    Float3 translation{0, 0, 0};
    Float4 rotation{0, 0, 0, 1};  // unit quaternion x, y, z, w
    Float3 scale{1, 1, 1};
};

struct Node {
    std::string name;
    Transform local;
    std::int32_t parent = kNoIndex;
    std::vector<std::int32_t> children;
    std::int32_t mesh = kNoIndex;
    std::int32_t camera = kNoIndex;  // into Model::cameras
    std::int32_t light = kNoIndex;   // into Model::lights
    std::int32_t skin = kNoIndex;    // into Model::skins; set only when the mesh can use it
    std::vector<float> weights;      // the node's morph weights; empty: the mesh's defaults
    // extras.rigidBody and extras.collider, as a scene file spells them (physics/README.md).
    std::optional<RigidBody> rigidBody;
    std::optional<Collider> collider;
};

struct NamedCamera {
    std::string name;
    Camera camera;
};

struct NamedLight {
    std::string name;
    Light light;
    bool rangeWasGiven = false;  // false: attenuationRadius comes from the no-range threshold
};

struct Model {
    std::filesystem::path sourcePath;
    std::vector<Node> nodes;
    std::vector<std::int32_t> rootNodes;  // roots of the scene to show (glTF `scene`, else 0)
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::vector<Rgba8Image> images;
    std::vector<NamedCamera> cameras;
    std::vector<NamedLight> lights;
    std::vector<SkinData> skins;
    std::vector<AnimationClip> animations;  // clips that failed validation are left out
};

}  // namespace candela::content
