#pragma once
// glTF skins and animation clips as plain data (what loadGltf() puts in Model::skins and
// Model::animations). Everything here has been validated by the loader: node and sampler
// indices are in range, key times are finite and strictly increasing, and every sampler holds
// exactly one value (three for CUBICSPLINE: in-tangent, value, out-tangent) per key.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace candela::content {

// Column-major 4x4, as glTF stores matrices (the layout of ecs::Mat4).
using Matrix4 = std::array<float, 16>;

struct SkinData {
    std::string name;
    std::vector<std::int32_t> joints;          // node indices; joint i is JOINTS_n value i
    std::vector<Matrix4> inverseBindMatrices;  // one per joint (identity when the file has none)
    std::int32_t skeleton = -1;                // the file's skeleton root node, -1 when not given
};

enum class Interpolation : std::uint8_t { Step, Linear, CubicSpline };
enum class AnimatedProperty : std::uint8_t { Translation, Rotation, Scale, Weights };

inline constexpr std::size_t kSlerpAngleFloats = 4;
// A LINEAR rotation interval is sampled with a corrected normalised lerp (ozz-animation
// samples with plain nlerp) where that stays within this arc angle (radians) of slerp, with
// exact slerp elsewhere (docs/speed-vs-error.md).
inline constexpr double kNlerpErrorTolerance = 2e-6;

struct AnimationSampler {
    Interpolation interpolation = Interpolation::Linear;
    std::uint32_t components = 0;  // floats per value: 3, 4 (x, y, z, w) or the target count
    std::vector<float> times;      // seconds, strictly increasing
    // Per key `components` floats; CUBICSPLINE keys hold in-tangent, value, out-tangent.
    std::vector<float> values;
    // LINEAR rotations: per key interval kSlerpAngleFloats floats, filled by
    // prepareSlerpAngles; empty: slerp computed when sampled. Either {k1, k2, sign, 1}: a
    // corrected normalised lerp (no sines; within kNlerpErrorTolerance of slerp), or
    // {angle, sine, sign, 0}: slerp (sine 0: plain lerp, the keys nearly parallel).
    std::vector<float> slerpAngles;
    // The largest arc angle (radians) between what sampling returns and exact slerp over the
    // corrected-nlerp intervals (0: none), measured by prepareSlerpAngles.
    float rotationErrorBound = 0;
};

struct AnimationChannel {
    std::int32_t node = -1;
    AnimatedProperty property = AnimatedProperty::Translation;
    std::int32_t sampler = -1;  // into AnimationClip::samplers
};

// The keys of a linearSharedTimes clip whose rotations all sample with the corrected nlerp,
// laid out so four rotation tracks sample together (structure of arrays, as ozz-animation's
// SamplingJob keeps its keys): one SSE expression interpolates four tracks and one sqrtps
// normalises them, with per lane the very arithmetic of sampleLinearAt and
// normalizeQuaternions (the same floats). Filled by markSharedKeyTimes; empty otherwise.
struct SharedKeyRotations {
    static constexpr std::size_t kLanes = 4;
    std::vector<std::uint32_t> rotationChannels;  // channel indices, in channel order
    std::vector<std::uint32_t> otherChannels;     // the translation and scale channels
    std::vector<std::uint32_t> nodes;             // each node a channel animates, once
    // Per key, per group of four rotation channels: x[4], y[4], z[4], w[4] (padding lanes
    // hold the identity).
    std::vector<float> keys;
    // Per key interval, per group: k1[4], k2[4], sign[4] (the corrected nlerp's constants).
    std::vector<float> corrections;
    std::size_t groups() const { return (rotationChannels.size() + kLanes - 1) / kLanes; }
    bool empty() const { return nodes.empty(); }
};

struct AnimationClip {
    std::string name;
    std::vector<AnimationSampler> samplers;
    std::vector<AnimationChannel> channels;
    float duration = 0;  // the last key time over all samplers
    // Every sampler is LINEAR with the very same key times (glTF exporters usually give a
    // clip's samplers one input accessor): sampling finds the key interval and its parameter
    // once per clip, not once per channel (the same values). Set by markSharedKeyTimes.
    bool linearSharedTimes = false;
    SharedKeyRotations sharedRotations;
};

}  // namespace candela::content
