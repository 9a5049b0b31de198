// glTF skins, morph targets and animation clips: the shared sample models load with the data
// their authors wrote, samplers interpolate as glTF appendix C says, and each kind of broken
// animation data gives an error naming the file and element while the model still loads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "candela/content/animation_sampling.h"
#include "candela/content/gltf_loader.h"
#include "gltf_test_documents.h"

namespace candela::content {
namespace {

using nlohmann::json;
using testing::BinaryBuffer;
using testing::bytesOf;

std::filesystem::path sampleModel(const std::string& name) {
    return std::filesystem::path(CANDELA_SHARED_ASSETS) / "models" / name / (name + ".glb");
}

Model loadClean(const std::string& name) {
    Diagnostics diagnostics;
    auto loaded = loadGltf(sampleModel(name), diagnostics);
    EXPECT_TRUE(loaded) << diagnostics.toString();
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.toString();
    return loaded ? std::move(*loaded) : Model{};
}

const AnimationClip* clipNamed(const Model& model, const std::string& name) {
    for (const AnimationClip& clip : model.animations)
        if (clip.name == name) return &clip;
    return nullptr;
}

// The pieces of a two-joint skinned quad with one translation clip; tests break one piece.
struct SkinnedQuad {
    std::vector<std::uint16_t> joints = {0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
    std::vector<float> weights = {0.5f, 0.5f, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0.25f, 0.25f, 0, 0};
    std::vector<float> times = {0, 1};
    std::vector<float> translations = {0, 0, 0, 0, 1, 0};
    int channelNode = 2;
    std::vector<float> inverseBind = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0,  0, 1,
                                      1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1};

    json document() const {
        BinaryBuffer buffer;
        const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
        const std::vector<std::uint16_t> indices = {0, 1, 2, 0, 2, 3};
        std::vector<json> views;
        std::vector<json> accessors;
        auto add = [&](const auto& values, int componentType, const char* type, std::size_t count) {
            const std::size_t offset = buffer.append(values);
            views.push_back({{"buffer", 0},
                             {"byteOffset", offset},
                             {"byteLength", values.size() * sizeof(values[0])}});
            accessors.push_back({{"bufferView", views.size() - 1},
                                 {"componentType", componentType},
                                 {"count", count},
                                 {"type", type}});
            return static_cast<int>(accessors.size() - 1);
        };
        const int p = add(positions, 5126, "VEC3", 4);
        accessors.back()["min"] = {0, 0, 0};
        accessors.back()["max"] = {1, 1, 0};
        const int i = add(indices, 5123, "SCALAR", 6);
        const int j = add(joints, 5123, "VEC4", joints.size() / 4);
        const int w = add(weights, 5126, "VEC4", weights.size() / 4);
        const int ibm = add(inverseBind, 5126, "MAT4", 2);
        const int in = add(times, 5126, "SCALAR", times.size());
        const int out = add(translations, 5126, "VEC3", translations.size() / 3);
        return {
            {"asset", {{"version", "2.0"}}},
            {"scene", 0},
            {"scenes", json::array({{{"nodes", {0, 1}}}})},
            {"nodes", json::array({{{"name", "quad"}, {"mesh", 0}, {"skin", 0}},
                                   {{"name", "root"}, {"children", {2}}},
                                   {{"name", "tip"}, {"translation", {0, 1, 0}}}})},
            {"meshes",
             json::array({{{"primitives",
                            json::array({{{"attributes",
                                           {{"POSITION", p}, {"JOINTS_0", j}, {"WEIGHTS_0", w}}},
                                          {"indices", i}}})}}})},
            {"skins", json::array({{{"joints", {1, 2}}, {"inverseBindMatrices", ibm}}})},
            {"animations",
             json::array(
                 {{{"name", "lift"},
                   {"samplers", json::array({{{"input", in}, {"output", out}}})},
                   {"channels",
                    json::array(
                        {{{"sampler", 0},
                          {"target", {{"node", channelNode}, {"path", "translation"}}}}})}}})},
            {"accessors", accessors},
            {"bufferViews", views},
            {"buffers",
             json::array({{{"byteLength", buffer.bytes.size()}, {"uri", buffer.dataUri()}}})},
        };
    }
};

std::optional<Model> load(const SkinnedQuad& quad, Diagnostics& diagnostics) {
    return loadGltfFromMemory(bytesOf(quad.document().dump()), "skinned.gltf", diagnostics);
}

TEST(GltfAnimation, SkinnedQuadLoadsWithNormalisedWeights) {
    Diagnostics diagnostics;
    auto model = load(SkinnedQuad{}, diagnostics);
    ASSERT_TRUE(model);
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.toString();
    ASSERT_EQ(model->skins.size(), 1u);
    EXPECT_EQ(model->nodes[0].skin, 0);
    EXPECT_EQ(model->skins[0].joints, (std::vector<std::int32_t>{1, 2}));
    EXPECT_FLOAT_EQ(model->skins[0].inverseBindMatrices[1][13], -1.0f);
    const Primitive& primitive = model->meshes[0].primitives[0];
    // Flat normals unweld the quad to 6 vertices; the influences follow.
    ASSERT_EQ(primitive.weights.size(), primitive.positions.size());
    ASSERT_EQ(primitive.joints.size(), primitive.positions.size());
    for (std::size_t v = 0; v < primitive.weights.size(); ++v) {
        const Float4& w = primitive.weights[v];
        EXPECT_FLOAT_EQ(w[0] + w[1] + w[2] + w[3], 1.0f);
        // Vertex 3's 0.25 + 0.25 is renormalised to 0.5 + 0.5, like vertex 0's.
        const Float3& p = primitive.positions[v];
        if (p[1] == 1.0f && p[0] == 0.0f) {
            EXPECT_FLOAT_EQ(w[0], 0.5f);
        }
    }
    ASSERT_EQ(model->animations.size(), 1u);
    EXPECT_FLOAT_EQ(model->animations[0].duration, 1.0f);
}

// Each broken piece: the error names the file and the element, the model loads, and only
// the deformation or the clip is dropped.
void expectDropped(const SkinnedQuad& quad, const std::string& element, const std::string& what,
                   bool skinDropped, bool clipDropped) {
    Diagnostics diagnostics;
    auto model = load(quad, diagnostics);
    ASSERT_TRUE(model) << diagnostics.toString();
    EXPECT_TRUE(diagnostics.hasErrors());
    bool named = false;
    for (const Diagnostic& message : diagnostics.messages) {
        named = named || (message.file == "skinned.gltf" && message.element == element &&
                          message.message.find(what) != std::string::npos);
    }
    EXPECT_TRUE(named) << "wanted " << element << ": ..." << what << "\n" << diagnostics.toString();
    ASSERT_EQ(model->meshes[0].primitives.size(), 1u) << "the mesh itself still loads";
    EXPECT_EQ(model->nodes[0].skin == kNoIndex, skinDropped);
    EXPECT_EQ(model->animations.empty(), clipDropped);
}

TEST(GltfAnimation, JointIndexOutOfRangeLeavesTheMeshInBindPose) {
    SkinnedQuad quad;
    quad.joints[4] = 7;
    expectDropped(quad, "nodes[0]", "uses joint 7 but skins[0] has 2 joints", true, false);
}

TEST(GltfAnimation, NegativeWeightsDropTheSkinning) {
    SkinnedQuad quad;
    quad.weights[1] = -0.5f;
    expectDropped(quad, "meshes[0].primitives[0]", "negative or NaN", true, false);
}

TEST(GltfAnimation, AllZeroWeightsDropTheSkinning) {
    SkinnedQuad quad;
    quad.weights[4] = 0;
    expectDropped(quad, "meshes[0].primitives[0]", "vertex 1 are all zero", true, false);
}

TEST(GltfAnimation, NanKeysDropTheClip) {
    SkinnedQuad quad;
    quad.translations[4] = std::nanf("");
    expectDropped(quad, "animations[0].samplers[0]", "output key 1 has a NaN/Inf value", false,
                  true);
    SkinnedQuad badTime;
    badTime.times[1] = std::nanf("");
    expectDropped(badTime, "animations[0].samplers[0]", "input key 1 is NaN/Inf", false, true);
}

// Issue 44: finite but absurd values made the skinned mesh vanish without a word. An inverse
// bind matrix holding 3e38 or flattening space drops the skin (bind pose, with an error);
// keyframes of 3e38 drop the clip; four weights of 3e38 normalise to a quarter each (their
// float sum overflowed and every weight became 0).
TEST(GltfAnimation, AbsurdFiniteValuesDropTheSkinOrClipByName) {
    SkinnedQuad huge;
    huge.inverseBind[12] = 3e38f;
    expectDropped(huge, "skins[0]", "values beyond 1e9", true, false);
    SkinnedQuad flat;
    std::fill(flat.inverseBind.begin() + 16, flat.inverseBind.end(), 0.0f);
    expectDropped(flat, "skins[0]", "matrix 1 is singular", true, false);
    SkinnedQuad keys;
    keys.translations[4] = 3e38f;
    expectDropped(keys, "animations[0].samplers[0]",
                  "output key 1 has a NaN/Inf value or one beyond", false, true);

    SkinnedQuad weights;
    std::fill(weights.weights.begin(), weights.weights.begin() + 4, 3e38f);
    weights.joints[2] = 1;  // four distinct influences of the same joint pair
    Diagnostics diagnostics;
    auto model = load(weights, diagnostics);
    ASSERT_TRUE(model);
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.toString();
    for (const Float4& w : model->meshes[0].primitives[0].weights) {
        EXPECT_FLOAT_EQ(w[0] + w[1] + w[2] + w[3], 1.0f);
    }
}

TEST(GltfAnimation, NonIncreasingKeyTimesDropTheClip) {
    SkinnedQuad quad;
    quad.times = {0.5f, 0.5f};
    expectDropped(quad, "animations[0].samplers[0]", "not increasing at key 1", false, true);
}

TEST(GltfAnimation, ChannelAimedAtAMissingNodeDropsTheClip) {
    SkinnedQuad quad;
    quad.channelNode = 9;
    expectDropped(quad, "animations[0].channels[0]", "targets node 9, which does not exist", false,
                  true);
}

TEST(GltfAnimation, SamplerOutputCountMismatchDropsTheClip) {
    SkinnedQuad quad;
    quad.translations = {0, 0, 0, 0, 1, 0, 0, 2, 0};
    expectDropped(quad, "animations[0].samplers[0]", "output has 9 values but 2 input keys need 6",
                  false, true);
}

// InterpolationTest.glb: one cube per (property, interpolation). Expected values worked out
// by hand from the file's keys (glTF 2.0 appendix C); the cubic rotation has non-zero tangents,
// so it checks their scaling by the key interval (0.4583 s there).
TEST(GltfAnimation, InterpolationTest) {
    const Model model = loadClean("InterpolationTest");
    struct Case {
        const char* clip;
        float time;
        std::vector<float> expected;
    };
    const std::vector<Case> cases = {
        {"Step Scale", 0.0f, {1, 1, 1}},  // before the first key (0.0417 s): the first value
        {"Step Scale", 0.6f, {0.5f, 0.5f, 0.5f}},
        {"Linear Scale", 0.6f, {0.7f, 0.7f, 0.7f}},             // 0.5 + 0.5 * 0.4
        {"CubicSpline Scale", 0.6f, {0.676f, 0.676f, 0.676f}},  // h00 0.648 * 0.5 + h01 0.352
        {"Step Rotation", 1.0f, {0, 0, -0.7071068f, 0.7071068f}},
        {"Linear Rotation", 0.2083333f, {0, 0, -0.1950903f, 0.9807853f}},  // 22.5 deg
        {"Linear Rotation", 1.0625f, {0, 0, -0.8314696f, 0.5555703f}},     // 112.5 deg
        {"CubicSpline Rotation", 0.6458333f, {0, 0, -0.5560857f, 0.8311249f}},
        {"CubicSpline Translation", 1.0f, {3.30518f, 7.408f, 0}},
        {"Linear Translation", 2.0f, {-3.297581f, 6, 0}},  // after the last key: clamped
        {"Step Translation", 0.5f, {0, 10, 0}},
    };
    for (const Case& c : cases) {
        const AnimationClip* clip = clipNamed(model, c.clip);
        ASSERT_NE(clip, nullptr) << c.clip;
        ASSERT_EQ(clip->channels.size(), 1u);
        const AnimationChannel& channel = clip->channels[0];
        std::vector<float> value(c.expected.size());
        sampleAnimation(clip->samplers[static_cast<std::size_t>(channel.sampler)], channel.property,
                        c.time, value);
        for (std::size_t i = 0; i < value.size(); ++i)
            EXPECT_NEAR(value[i], c.expected[i], 1e-5)
                << c.clip << " at " << c.time << " [" << i << "]";
    }
}

TEST(GltfAnimation, CubicSplineTangentsAreScaledByTheKeyInterval) {
    AnimationSampler sampler;
    sampler.interpolation = Interpolation::CubicSpline;
    sampler.components = 1;
    sampler.times = {1, 3};
    sampler.values = {0, 0, 1, /* key 1: */ 0, 0, 0};  // out-tangent 1 at key 0, values 0
    float value = 0;
    sampleAnimation(sampler, AnimatedProperty::Translation, 2.0f, std::span(&value, 1));
    // h10(0.5) = 0.125, times the interval 2 s, times the tangent 1.
    EXPECT_NEAR(value, 0.25f, 1e-6);
}

TEST(GltfAnimation, FoxHasItsSkinAndThreeClips) {
    const Model model = loadClean("Fox");
    ASSERT_EQ(model.skins.size(), 1u);
    EXPECT_EQ(model.skins[0].joints.size(), 24u);
    ASSERT_EQ(model.animations.size(), 3u);
    EXPECT_NE(clipNamed(model, "Survey"), nullptr);
    EXPECT_NE(clipNamed(model, "Walk"), nullptr);
    EXPECT_NE(clipNamed(model, "Run"), nullptr);
    bool skinnedNode = false;
    for (const Node& node : model.nodes)
        skinnedNode = skinnedNode || node.skin == 0;
    EXPECT_TRUE(skinnedNode);
    for (const Mesh& mesh : model.meshes) {
        for (const Primitive& p : mesh.primitives) {
            ASSERT_EQ(p.weights.size(), p.positions.size());
            for (const Float4& w : p.weights)
                EXPECT_NEAR(w[0] + w[1] + w[2] + w[3], 1.0f, 1e-5);
        }
    }
}

TEST(GltfAnimation, CesiumManAndSimpleSkinsLoadClean) {
    for (const char* name : {"CesiumMan", "RiggedSimple", "BoxAnimated"}) {
        const Model model = loadClean(name);
        EXPECT_FALSE(model.animations.empty()) << name;
    }
    Diagnostics diagnostics;
    auto simple = loadGltf(
        std::filesystem::path(CANDELA_SHARED_ASSETS) / "models" / "SimpleSkin" / "SimpleSkin.gltf",
        diagnostics);
    ASSERT_TRUE(simple);
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.toString();
    EXPECT_EQ(simple->skins.size(), 1u);
}

// Morph weights sampled at key times equal the file's keys, and halfway between two LINEAR
// keys their mean.
TEST(GltfAnimation, MorphWeightsAtTimesMatchTheFilesKeys) {
    for (const char* name : {"AnimatedMorphCube", "MorphPrimitivesTest"}) {
        const Model model = loadClean(name);
        std::size_t targets = 0;
        for (const Mesh& mesh : model.meshes) {
            targets = std::max(targets, mesh.defaultWeights.size());
            for (const Primitive& p : mesh.primitives) {
                for (const MorphTarget& t : p.morphTargets)
                    EXPECT_EQ(t.positionDeltas.size(), p.positions.size()) << name;
            }
        }
        EXPECT_GE(targets, 1u) << name;
        for (const AnimationClip& clip : model.animations) {
            for (const AnimationChannel& channel : clip.channels) {
                if (channel.property != AnimatedProperty::Weights) continue;
                const AnimationSampler& s =
                    clip.samplers[static_cast<std::size_t>(channel.sampler)];
                const std::size_t n = s.components;
                const std::size_t stride =
                    s.interpolation == Interpolation::CubicSpline ? 3 * n : n;
                const std::size_t offset = s.interpolation == Interpolation::CubicSpline ? n : 0;
                std::vector<float> value(n);
                for (std::size_t k = 0; k < s.times.size(); ++k) {
                    sampleAnimation(s, channel.property, s.times[k], value);
                    for (std::size_t c = 0; c < n; ++c)
                        EXPECT_NEAR(value[c], s.values[k * stride + offset + c], 1e-6) << name;
                    if (k + 1 < s.times.size() && s.interpolation == Interpolation::Linear) {
                        sampleAnimation(s, channel.property, 0.5f * (s.times[k] + s.times[k + 1]),
                                        value);
                        for (std::size_t c = 0; c < n; ++c)
                            EXPECT_NEAR(value[c],
                                        0.5f * (s.values[k * n + c] + s.values[(k + 1) * n + c]),
                                        1e-5)
                                << name;
                    }
                }
            }
        }
    }
}

}  // namespace
// LINEAR rotations: sampling (corrected nlerp where prepareSlerpAngles measured it within
// kNlerpErrorTolerance, slerp elsewhere) against slerp in double precision, at 97 times per
// key interval, in every clip of Fox and CesiumMan: within the sampler's measured bound plus
// float rounding.
TEST(GltfAnimation, SampledRotationsStayWithinTheNlerpBoundOfSlerp) {
    constexpr double kFloatRounding = 1e-6;
    double worst = 0;
    for (const char* name : {"Fox", "CesiumMan"}) {
        const Model model = loadClean(name);
        for (const AnimationClip& clip : model.animations) {
            for (const AnimationChannel& channel : clip.channels) {
                if (channel.property != AnimatedProperty::Rotation) continue;
                const AnimationSampler& sampler =
                    clip.samplers[static_cast<std::size_t>(channel.sampler)];
                if (sampler.interpolation != Interpolation::Linear) continue;
                EXPECT_LE(sampler.rotationErrorBound, kNlerpErrorTolerance);
                for (std::size_t k = 0; k + 1 < sampler.times.size(); ++k) {
                    const float* a = &sampler.values[4 * k];
                    const float* b = &sampler.values[4 * (k + 1)];
                    double dot = 0, lengthA = 0, lengthB = 0;
                    for (int c = 0; c < 4; ++c) {
                        dot += static_cast<double>(a[c]) * b[c];
                        lengthA += static_cast<double>(a[c]) * a[c];
                        lengthB += static_cast<double>(b[c]) * b[c];
                    }
                    const double sign = dot < 0 ? -1 : 1;
                    const double theta =
                        std::acos(std::min(1.0, std::fabs(dot) / std::sqrt(lengthA * lengthB)));
                    for (int i = 1; i < 98; ++i) {
                        const double t = i / 98.0;
                        const double wa =
                            theta < 1e-9 ? 1 - t : std::sin((1 - t) * theta) / std::sin(theta);
                        const double wb = theta < 1e-9 ? t : std::sin(t * theta) / std::sin(theta);
                        double exact[4], length = 0;
                        for (int c = 0; c < 4; ++c) {
                            exact[c] = wa * a[c] / std::sqrt(lengthA) +
                                       sign * wb * b[c] / std::sqrt(lengthB);
                            length += exact[c] * exact[c];
                        }
                        const float time = static_cast<float>(
                            sampler.times[k] + t * (sampler.times[k + 1] - sampler.times[k]));
                        float sampled[4];
                        sampleAnimation(sampler, AnimatedProperty::Rotation, time, sampled);
                        double difference = 0;
                        for (int c = 0; c < 4; ++c)
                            difference = std::max(
                                difference, std::fabs(sampled[c] - exact[c] / std::sqrt(length)));
                        worst = std::max(worst, difference);
                        ASSERT_LE(difference, sampler.rotationErrorBound + kFloatRounding)
                            << name << " clip " << clip.name << " key " << k << " t " << t;
                    }
                }
            }
        }
    }
    std::printf("largest difference from slerp: %.3g\n", worst);
}

}  // namespace candela::content
