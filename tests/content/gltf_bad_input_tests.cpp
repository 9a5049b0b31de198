// Broken glTF input: every case must give a message naming file, element and problem, load
// what it can, and never crash (these also run under ASan/UBSan).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "candela/content/component_validation.h"
#include "candela/content/gltf_loader.h"
#include "candela/content/light_units.h"
#include "gltf_test_documents.h"
#include "test_paths.h"

namespace candela::content {
namespace {

using nlohmann::json;
using testing::bytesOf;
using testing::quadDocument;

std::optional<Model> loadJson(const json& doc, Diagnostics& diagnostics) {
    return loadGltfFromMemory(bytesOf(doc.dump()), "broken.gltf", diagnostics);
}

std::vector<std::byte> readAsset(const std::string& name) {
    std::ifstream in(
        std::filesystem::path(CANDELA_SHARED_ASSETS) / "models" / name / (name + ".glb"),
        std::ios::binary);
    std::vector<char> chars((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<std::byte> bytes(chars.size());
    std::memcpy(bytes.data(), chars.data(), chars.size());
    return bytes;
}

// A quad document plus a second primitive, so tests can break one and keep the other.
json twoPrimitiveDocument() {
    json doc = quadDocument();
    doc["meshes"][0]["primitives"].push_back(doc["meshes"][0]["primitives"][0]);
    return doc;
}

TEST(GltfBadInput, TruncatedGlbNeverCrashesAndNamesTheFile) {
    const std::vector<std::byte> glb = readAsset("BoxTextured");
    for (std::size_t length = 0; length < glb.size(); length += (length < 64 ? 1 : 97)) {
        Diagnostics diagnostics;
        auto m = loadGltfFromMemory(std::span(glb.data(), length), "cut.glb", diagnostics);
        EXPECT_FALSE(m) << length;
        EXPECT_TRUE(diagnostics.mentions("cut.glb")) << length;
    }
}

TEST(GltfBadInput, GarbageAndEmptyInputAreErrors) {
    for (const std::string text : {"", "garbage", "{", "[1,2,3]", "{\"asset\":{}}",
                                   "{\"asset\":{\"version\":\"1.0\"}}", "glTF\x02\0\0\0"}) {
        Diagnostics diagnostics;
        EXPECT_FALSE(loadGltfFromMemory(bytesOf(text), "junk.gltf", diagnostics)) << text;
        EXPECT_TRUE(diagnostics.hasErrors()) << text;
        EXPECT_TRUE(diagnostics.mentions("junk.gltf")) << text;
    }
}

TEST(GltfBadInput, OutOfRangeIndexSkipsOnlyThatPrimitive) {
    json doc = twoPrimitiveDocument();
    testing::BinaryBuffer buffer;
    buffer.append(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 9});
    doc["buffers"].push_back({{"byteLength", buffer.bytes.size()}, {"uri", buffer.dataUri()}});
    doc["bufferViews"].push_back({{"buffer", 1}, {"byteLength", 12}});
    doc["accessors"].push_back(
        {{"bufferView", 3}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}});
    doc["meshes"][0]["primitives"][1]["indices"] = 3;
    Diagnostics diagnostics;
    auto m = loadJson(doc, diagnostics);
    ASSERT_TRUE(m);
    EXPECT_EQ(m->meshes[0].primitives.size(), 1u);
    EXPECT_TRUE(diagnostics.mentions("broken.gltf: meshes[0].primitives[1]: error: index 9"))
        << diagnostics.toString();
}

// Lines read their indices as triangles do: an index past the positions skips the wire alone,
// and the message names what was skipped.
TEST(GltfBadInput, OutOfRangeLineIndexSkipsOnlyThatWire) {
    json doc = quadDocument();
    doc["materials"] = json::array({{{"name", "cable"}, {"extras", {{"wireRadius", 0.02}}}}});
    testing::BinaryBuffer buffer;
    buffer.append(std::vector<std::uint16_t>{0, 1, 2, 9});
    doc["buffers"].push_back({{"byteLength", buffer.bytes.size()}, {"uri", buffer.dataUri()}});
    doc["bufferViews"].push_back({{"buffer", 1}, {"byteLength", 8}});
    doc["accessors"].push_back(
        {{"bufferView", 3}, {"componentType", 5123}, {"count", 4}, {"type", "SCALAR"}});
    const json lines = {{"attributes", {{"POSITION", 0}}}, {"mode", 1}, {"material", 0}};
    doc["meshes"][0]["primitives"].push_back(lines);
    doc["meshes"][0]["primitives"].push_back(lines);
    doc["meshes"][0]["primitives"][2]["indices"] = 3;
    Diagnostics diagnostics;
    auto m = loadJson(doc, diagnostics);
    ASSERT_TRUE(m);
    EXPECT_EQ(m->meshes[0].wires.size(), 1u) << diagnostics.toString();
    EXPECT_TRUE(
        diagnostics.mentions("broken.gltf: meshes[0].primitives[2]: error: index 9 at "
                             "position 3 is not below the vertex count 4; wire skipped"))
        << diagnostics.toString();
}

TEST(GltfBadInput, AccessorsOverrunningTheirBufferAreRejected) {
    struct Case {
        const char* what;
        json accessorPatch;
    };
    const Case cases[] = {
        {"count past the view", {{"count", 5}}},
        {"absurd count", {{"count", 4000000000u}}},
        {"offset past the view", {{"byteOffset", 40}}},
        {"missing view", {{"bufferView", 99}}},
        {"wrong type", {{"type", "VEC2"}}},
    };
    for (const Case& c : cases) {
        json doc = twoPrimitiveDocument();
        doc["accessors"].push_back(doc["accessors"][0]);
        doc["accessors"][3].update(c.accessorPatch);
        doc["meshes"][0]["primitives"][1]["attributes"]["POSITION"] = 3;
        Diagnostics diagnostics;
        auto m = loadJson(doc, diagnostics);
        ASSERT_TRUE(m) << c.what << "\n" << diagnostics.toString();
        EXPECT_EQ(m->meshes[0].primitives.size(), 1u) << c.what;
        EXPECT_TRUE(diagnostics.mentions("meshes[0].primitives[1]")) << c.what;
    }
}

TEST(GltfBadInput, BufferViewOutsideItsBufferIsRejected) {
    json doc = quadDocument();
    doc["bufferViews"][2]["byteLength"] = 1000;
    Diagnostics diagnostics;
    auto m = loadJson(doc, diagnostics);
    // tinygltf may reject the file itself or we reject the primitive; either way: no crash, a
    // message, and no primitive reading outside the buffer.
    if (m) {
        EXPECT_TRUE(m->meshes[0].primitives.empty());
    }
    EXPECT_TRUE(diagnostics.hasErrors());
}

TEST(GltfBadInput, NonFinitePositionsSkipThePrimitive) {
    json doc = twoPrimitiveDocument();
    testing::BinaryBuffer buffer;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    buffer.append(std::vector<float>{0, 0, 0, 1, 0, 0, nan, 1, 0, 0, 1, 0});
    doc["buffers"].push_back({{"byteLength", buffer.bytes.size()}, {"uri", buffer.dataUri()}});
    doc["bufferViews"].push_back({{"buffer", 1}, {"byteLength", 48}});
    doc["accessors"].push_back(
        {{"bufferView", 3}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}});
    doc["meshes"][0]["primitives"][1]["attributes"]["POSITION"] = 3;
    Diagnostics diagnostics;
    auto m = loadJson(doc, diagnostics);
    ASSERT_TRUE(m);
    EXPECT_EQ(m->meshes[0].primitives.size(), 1u);
    EXPECT_TRUE(diagnostics.mentions("meshes[0].primitives[1]: error: POSITION has NaN/Inf"));
}

TEST(GltfBadInput, NonFiniteNodeTransformFallsBackToIdentity) {
    json doc = quadDocument();
    doc["nodes"][0]["translation"] = {1e39, 0, 0};  // overflows float: +Inf
    doc["nodes"].push_back({{"name", "ok"}, {"translation", {1, 2, 3}}});
    doc["scenes"][0]["nodes"].push_back(1);
    Diagnostics diagnostics;
    auto m = loadJson(doc, diagnostics);
    ASSERT_TRUE(m);
    EXPECT_EQ(m->nodes[0].local.translation, (Float3{0, 0, 0}));
    EXPECT_EQ(m->nodes[1].local.translation, (Float3{1, 2, 3}));
    EXPECT_TRUE(diagnostics.mentions("nodes[0]: error: transform has NaN/Inf"));
}

TEST(GltfBadInput, UnknownRequiredExtensionRefusesTheFile) {
    json doc = quadDocument();
    doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    Diagnostics diagnostics;
    EXPECT_FALSE(loadJson(doc, diagnostics));
    EXPECT_TRUE(diagnostics.mentions("KHR_draco_mesh_compression is not supported"));
    // Used but not required: a warning, and the file loads.
    doc.erase("extensionsRequired");
    Diagnostics usedOnly;
    EXPECT_TRUE(loadJson(doc, usedOnly));
    EXPECT_FALSE(usedOnly.hasErrors());
}

TEST(GltfBadInput, MissingExternalBufferAndImageAreReported) {
    const auto path = testing::tempPath("missing.gltf");
    json doc = quadDocument();
    doc["images"] = json::array({{{"uri", "no-such-image.png"}}});
    doc["textures"] = json::array({{{"source", 0}}});
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    std::ofstream(path) << doc.dump();
    Diagnostics imageDiagnostics;
    auto m = loadGltf(path, imageDiagnostics);
    ASSERT_TRUE(m) << imageDiagnostics.toString();
    EXPECT_TRUE(m->images.at(0).isFallback);
    EXPECT_TRUE(imageDiagnostics.mentions("images[0]"));

    doc["buffers"][0]["uri"] = "no-such-buffer.bin";
    std::ofstream(path) << doc.dump();
    Diagnostics bufferDiagnostics;
    EXPECT_FALSE(loadGltf(path, bufferDiagnostics));
    EXPECT_TRUE(bufferDiagnostics.mentions("no-such-buffer.bin")) << bufferDiagnostics.toString();
}

TEST(GltfBadInput, BadReferencesFallBackAndHierarchyStaysAForest) {
    json doc = quadDocument();
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 7}};
    doc["meshes"][0]["primitives"][0]["material"] = 5;
    doc["nodes"] = json::array({
        {{"name", "a"}, {"children", {1}}, {"mesh", 3}},
        {{"name", "b"}, {"children", {2, 1, 42}}},
        {{"name", "c"}, {"children", {0}}},  // cycle a -> b -> c -> a
        {{"name", "d"}, {"children", {2}}},  // second parent for c
    });
    doc["scenes"][0]["nodes"] = {0, 3, 99};
    Diagnostics diagnostics;
    auto m = loadJson(doc, diagnostics);
    ASSERT_TRUE(m);
    EXPECT_EQ(m->meshes[0].primitives[0].material, kNoIndex);
    EXPECT_TRUE(diagnostics.mentions("materials[0].pbrMetallicRoughness.baseColorTexture"));
    const std::int32_t fallback = m->materials[0].baseColorTexture.texture;
    ASSERT_GE(fallback, 0);
    EXPECT_TRUE(
        m->images[static_cast<std::size_t>(m->textures[static_cast<std::size_t>(fallback)].image)]
            .isFallback);
    EXPECT_EQ(m->nodes[0].mesh, kNoIndex);
    // Every parent chain ends at a root within nodes.size() steps.
    for (std::size_t n = 0; n < m->nodes.size(); ++n) {
        std::int32_t at = static_cast<std::int32_t>(n);
        std::size_t steps = 0;
        while (at != kNoIndex && steps <= m->nodes.size()) {
            at = m->nodes[static_cast<std::size_t>(at)].parent;
            ++steps;
        }
        EXPECT_EQ(at, kNoIndex) << "node " << n << " is on a cycle";
    }
    EXPECT_TRUE(diagnostics.mentions("nodes[1]: error: child 1"));
    EXPECT_TRUE(diagnostics.mentions("child 42"));
    EXPECT_TRUE(diagnostics.mentions("parent cycle"));
}

TEST(GltfBadInput, DeeplyNestedExtrasAreRefusedBeforeParsing) {
    json doc = quadDocument();
    std::string text = doc.dump();
    text.insert(text.size() - 1,
                ",\"extras\":" + std::string(100000, '[') + std::string(100000, ']'));
    Diagnostics diagnostics;
    EXPECT_FALSE(loadGltfFromMemory(bytesOf(text), "deep.gltf", diagnostics));
    EXPECT_TRUE(diagnostics.mentions("nested deeper")) << diagnostics.toString();
}

TEST(GltfBadInput, DeepHierarchyAndManyNodesDoNotRecurse) {
    json doc = quadDocument();
    doc["nodes"] = json::array();
    const int depth = 20000;
    for (int i = 0; i < depth; ++i) {
        json node = {{"name", "n"}};
        if (i + 1 < depth) node["children"] = {i + 1};
        doc["nodes"].push_back(node);
    }
    doc["scenes"][0]["nodes"] = {0};
    Diagnostics diagnostics;
    auto m = loadJson(doc, diagnostics);
    ASSERT_TRUE(m);
    EXPECT_EQ(m->nodes.back().parent, depth - 2);
}

// Issue 22: a point light of 3e38 cd overflowed to Inf lumens and was switched off without a
// word; emission of 3e38 x 3e38 made NaN frames. Both are clamped with a warning naming the
// element, and the light still shines.
TEST(GltfBadInput, AbsurdLightAndEmissionAreClampedWithAWarning) {
    json doc = quadDocument();
    doc["extensionsUsed"] = {"KHR_lights_punctual", "KHR_materials_emissive_strength"};
    doc["extensions"]["KHR_lights_punctual"]["lights"] =
        json::array({{{"type", "point"}, {"intensity", 3e38}}});
    doc["nodes"][0]["extensions"]["KHR_lights_punctual"]["light"] = 0;
    doc["materials"][0]["emissiveFactor"] = {1.0, 1.0, 1.0};
    doc["materials"][0]["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] = 3e38;
    Diagnostics diagnostics;
    auto m = loadJson(doc, diagnostics);
    ASSERT_TRUE(m) << diagnostics.toString();
    ASSERT_EQ(m->lights.size(), 1u);
    const Light& light = m->lights[0].light;
    EXPECT_TRUE(std::isfinite(light.lumens));
    EXPECT_LE(light.lumens, kMaxLumens);
    EXPECT_GT(light.lumens, 0.999f * kMaxLumens);
    EXPECT_GT(light.attenuationRadius, 0.0f);
    EXPECT_TRUE(diagnostics.mentions("KHR_lights_punctual.lights[0]")) << diagnostics.toString();
    EXPECT_TRUE(diagnostics.mentions("is beyond the limit of")) << diagnostics.toString();
    const Material& material = m->materials[0];
    EXPECT_LE(material.emissiveStrength, kMaxEmissiveLuminance);
    EXPECT_TRUE(diagnostics.mentions("materials[0]: warning: emissiveStrength"))
        << diagnostics.toString();
}

}  // namespace
}  // namespace candela::content
