// glTF features beyond the sample models, on generated documents: external and data-URI
// buffers, GLB, KHR extensions, engine extras, lights, cameras, strips, vertex colours.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "candela/content/gltf_loader.h"
#include "candela/content/hair.h"
#include "candela/content/light_texture.h"
#include "candela/content/light_units.h"
#include "candela/content/model_instantiation.h"
#include "candela/content/png_writer.h"
#include "candela/content/procedural_mesh.h"
#include "candela/ecs/registry.h"
#include "gltf_test_documents.h"
#include "test_paths.h"

namespace candela::content {
namespace {

using nlohmann::json;
using testing::bytesOf;
using testing::quadDocument;

std::optional<Model> loadJson(const json& doc, Diagnostics& diagnostics,
                              const std::filesystem::path& path = "test.gltf") {
    return loadGltfFromMemory(bytesOf(doc.dump()), path, diagnostics);
}

TEST(GltfFeatures, DataUriQuadLoadsWithFlatNormalsAndTangents) {
    Diagnostics diagnostics;
    auto m = loadJson(quadDocument(), diagnostics);
    ASSERT_TRUE(m) << diagnostics.toString();
    EXPECT_TRUE(diagnostics.messages.empty()) << diagnostics.toString();
    const Primitive& p = m->meshes.at(0).primitives.at(0);
    EXPECT_TRUE(p.normalsGenerated);
    EXPECT_EQ(p.positions.size(), 6u) << "flat normals unweld the two triangles";
    for (const Float3& n : p.normals)
        EXPECT_EQ(n, (Float3{0, 0, 1}));
    for (const Float4& t : p.tangents) {
        EXPECT_NEAR(t[0], 1.0f, 1e-6f);
        EXPECT_EQ(t[3], 1.0f) << "u along +X, v down the image: not mirrored";
    }
    EXPECT_EQ(m->nodes.at(0).name, "quad");
    EXPECT_EQ(m->meshes.at(0).name, "quadMesh");
}

TEST(GltfFeatures, ExternalBufferAndGlbGiveTheSameGeometry) {
    json doc = quadDocument();
    // Move the data-URI buffer into a .bin file beside the .gltf.
    std::string uri = doc["buffers"][0]["uri"];
    const std::string payload = uri.substr(uri.find(',') + 1);
    Diagnostics decodeDiagnostics;
    auto reference = loadJson(doc, decodeDiagnostics);
    ASSERT_TRUE(reference);

    // The same bytes the data URI holds, written as a file.
    testing::BinaryBuffer buffer;
    buffer.append(std::vector<float>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
    buffer.append(std::vector<float>{0, 1, 1, 1, 1, 0, 0, 0});
    buffer.append(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3});
    ASSERT_EQ(testing::base64(buffer.bytes), payload);

    const auto gltfPath = testing::tempPath("quad.gltf");
    {
        std::ofstream bin(gltfPath.parent_path() / "quad.bin", std::ios::binary);
        bin.write(reinterpret_cast<const char*>(buffer.bytes.data()),
                  static_cast<std::streamsize>(buffer.bytes.size()));
        doc["buffers"][0]["uri"] = "quad.bin";
        std::ofstream(gltfPath) << doc.dump(2);
    }
    Diagnostics diagnostics;
    auto external = loadGltf(gltfPath, diagnostics);
    ASSERT_TRUE(external) << diagnostics.toString();
    EXPECT_EQ(external->meshes[0].primitives[0].positions,
              reference->meshes[0].primitives[0].positions);

    // GLB: JSON chunk + BIN chunk, buffer without uri.
    json glbDoc = doc;
    glbDoc["buffers"][0].erase("uri");
    std::string jsonText = glbDoc.dump();
    while (jsonText.size() % 4 != 0)
        jsonText += ' ';
    std::vector<std::uint8_t> bin = buffer.bytes;
    while (bin.size() % 4 != 0)
        bin.push_back(0);
    std::vector<std::uint8_t> glb;
    auto u32 = [&](std::uint32_t v) {
        for (int i = 0; i < 4; ++i)
            glb.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    };
    u32(0x46546C67);
    u32(2);
    u32(static_cast<std::uint32_t>(12 + 8 + jsonText.size() + 8 + bin.size()));
    u32(static_cast<std::uint32_t>(jsonText.size()));
    u32(0x4E4F534A);
    glb.insert(glb.end(), jsonText.begin(), jsonText.end());
    u32(static_cast<std::uint32_t>(bin.size()));
    u32(0x004E4942);
    glb.insert(glb.end(), bin.begin(), bin.end());
    Diagnostics glbDiagnostics;
    auto fromGlb = loadGltfFromMemory(std::as_bytes(std::span(glb)), "quad.glb", glbDiagnostics);
    ASSERT_TRUE(fromGlb) << glbDiagnostics.toString();
    EXPECT_EQ(fromGlb->meshes[0].primitives[0].positions,
              reference->meshes[0].primitives[0].positions);
}

TEST(GltfFeatures, PunctualLightsConvertToPhotometricEngineUnits) {
    json doc = quadDocument();
    doc["extensionsUsed"] = {"KHR_lights_punctual"};
    doc["extensions"]["KHR_lights_punctual"]["lights"] = json::array({
        {{"type", "point"}, {"intensity", 10.0}, {"range", 7.5}, {"color", {1, 0.5, 0.25}}},
        {{"type", "spot"},
         {"intensity", 20.0},
         {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.6}}}},
        {{"type", "directional"}, {"intensity", 3.5}},
        {{"type", "point"},
         {"intensity", 100.0},
         {"extras", {{"sourceRadius", 0.25}, {"sourceLength", 2.0}}}},
    });
    doc["nodes"][0]["extensions"]["KHR_lights_punctual"]["light"] = 3;
    Diagnostics diagnostics;
    auto m = loadJson(doc, diagnostics);
    ASSERT_TRUE(m) << diagnostics.toString();
    ASSERT_EQ(m->lights.size(), 4u);
    const float fourPi = 4.0f * std::numbers::pi_v<float>;

    const Light& point = m->lights[0].light;
    EXPECT_EQ(point.type, LightType::Point);
    EXPECT_FLOAT_EQ(point.lumens, 10.0f * fourPi);
    EXPECT_FLOAT_EQ(point.attenuationRadius, 7.5f);
    EXPECT_TRUE(m->lights[0].rangeWasGiven);
    EXPECT_EQ(point.color, (std::array<float, 3>{1, 0.5f, 0.25f}));

    const Light& spot = m->lights[1].light;
    EXPECT_EQ(spot.type, LightType::Spot);
    EXPECT_FLOAT_EQ(spot.lumens, 20.0f * fourPi) << "spot lumens ignore the cone (SPEC.md)";
    EXPECT_FLOAT_EQ(spot.innerConeAngle, 0.2f);
    EXPECT_FLOAT_EQ(spot.outerConeAngle, 0.6f);
    EXPECT_FALSE(m->lights[1].rangeWasGiven);
    // No range: the radius where 20 cd falls to the threshold illuminance.
    const float radius = std::sqrt(20.0f / kNoRangeIlluminanceThresholdLux);
    EXPECT_FLOAT_EQ(spot.attenuationRadius, radius);
    EXPECT_NEAR(20.0f / (radius * radius), kNoRangeIlluminanceThresholdLux, 1e-6f);

    EXPECT_EQ(m->lights[2].light.type, LightType::Directional);
    EXPECT_FLOAT_EQ(m->lights[2].light.lux, 3.5f);

    EXPECT_FLOAT_EQ(m->lights[3].light.sourceRadius, 0.25f);
    EXPECT_FLOAT_EQ(m->lights[3].light.sourceLength, 2.0f);
    EXPECT_EQ(m->nodes[0].light, 3);
}

// Issue 15: extras.shape makes a point light a one-sided rect or disk; the glTF intensity is
// the on-axis intensity (cd), so lumens = pi x intensity. A shape without an area is an error
// naming the light, which then emits nothing.
TEST(GltfFeatures, ExtrasShapeMakesRectAndDiskLights) {
    json doc = quadDocument();
    doc["extensionsUsed"] = {"KHR_lights_punctual"};
    doc["extensions"]["KHR_lights_punctual"]["lights"] = json::array({
        {{"type", "point"},
         {"intensity", 50.0},
         {"extras", {{"shape", "rect"}, {"width", 1.5}, {"height", 0.5}}}},
        {{"type", "spot"},
         {"intensity", 8.0},
         {"spot", {{"outerConeAngle", 0.6}}},
         {"extras", {{"shape", "disk"}, {"sourceRadius", 0.3}}}},
        {{"type", "point"},
         {"intensity", 5.0},
         {"extras", {{"shape", "rect"}, {"width", -2.0}, {"height", 1.0}}}},
        {{"type", "point"}, {"intensity", 5.0}, {"extras", {{"shape", "disk"}}}},
        {{"type", "point"}, {"intensity", 5.0}, {"extras", {{"shape", "hexagon"}}}},
    });
    Diagnostics diagnostics;
    auto m = loadJson(doc, diagnostics);
    ASSERT_TRUE(m) << diagnostics.toString();
    ASSERT_EQ(m->lights.size(), 5u);
    const float pi = std::numbers::pi_v<float>;
    const Light& rect = m->lights[0].light;
    EXPECT_EQ(rect.type, LightType::Rect);
    EXPECT_FLOAT_EQ(rect.lumens, pi * 50.0f);
    EXPECT_FLOAT_EQ(rect.width, 1.5f);
    EXPECT_FLOAT_EQ(rect.height, 0.5f);
    const Light& disk = m->lights[1].light;
    EXPECT_EQ(disk.type, LightType::Disk);
    EXPECT_FLOAT_EQ(disk.lumens, pi * 8.0f);
    EXPECT_FLOAT_EQ(disk.sourceRadius, 0.3f);
    // Negative width, zero-area disk: skipped (no light) with errors naming them.
    EXPECT_EQ(m->lights[2].light.lumens, 0.0f);
    EXPECT_EQ(m->lights[3].light.lumens, 0.0f);
    EXPECT_EQ(m->lights[4].light.type, LightType::Point);
    const std::string messages = diagnostics.toString();
    EXPECT_NE(messages.find("lights[2].extras.width"), std::string::npos) << messages;
    EXPECT_NE(messages.find("lights[3]"), std::string::npos) << messages;
    EXPECT_NE(messages.find("lights[4].extras.shape"), std::string::npos) << messages;
}

// Issue 15: extras.texture names a rect light's emissive image, relative to the glTF file. A
// file that cannot be used is an error naming extras.texture, the light and the file; the rect
// stays a rect, untextured.
TEST(GltfFeatures, ExtrasTextureGivesARectItsImage) {
    const std::filesystem::path gltf = testing::tempPath("screen.gltf");
    const std::uint8_t texels[2 * 1 * 4] = {255, 0, 0, 255, 0, 0, 255, 255};
    ASSERT_EQ(writePng(gltf.parent_path() / "card.png", 2, 1, 4, texels), "");
    json doc = quadDocument();
    doc["extensionsUsed"] = {"KHR_lights_punctual"};
    auto rect = [](const char* name, const char* texture) {
        return json{
            {"type", "point"},
            {"name", name},
            {"intensity", 50.0},
            {"extras", {{"shape", "rect"}, {"width", 1.6}, {"height", 0.9}, {"texture", texture}}}};
    };
    doc["extensions"]["KHR_lights_punctual"]["lights"] =
        json::array({rect("screen", "card.png"), rect("broken", "missing.png")});
    Diagnostics diagnostics;
    auto m = loadJson(doc, diagnostics, gltf);
    ASSERT_TRUE(m) << diagnostics.toString();
    ASSERT_EQ(m->lights.size(), 2u);
    const auto screen = findLightTexture(m->lights[0].light.texture);
    ASSERT_TRUE(screen);
    EXPECT_EQ(screen->file, "card.png");
    ASSERT_TRUE(screen->image);
    EXPECT_EQ(screen->image->width, 2u);
    EXPECT_EQ(screen->image->rgba[0], 255);
    EXPECT_EQ(screen->image->rgba[6], 255);
    const Light& broken = m->lights[1].light;
    EXPECT_EQ(broken.type, LightType::Rect);
    EXPECT_GT(broken.lumens, 0.0f);  // still lights, untextured
    const auto missing = findLightTexture(broken.texture);
    ASSERT_TRUE(missing);  // the file name is kept (a scene saved again names it)
    EXPECT_EQ(missing->file, "missing.png");
    EXPECT_FALSE(missing->image);
    const std::string messages = diagnostics.toString();
    EXPECT_NE(messages.find("lights[1].extras.texture"), std::string::npos) << messages;
    EXPECT_NE(messages.find("'broken'"), std::string::npos) << messages;
    EXPECT_NE(messages.find("missing.png"), std::string::npos) << messages;
    EXPECT_EQ(messages.find("lights[0]"), std::string::npos) << messages;
}

TEST(GltfFeatures, MaterialExtensionsAndEngineExtras) {
    json doc = quadDocument();
    doc["extensionsUsed"] = {"KHR_materials_emissive_strength", "KHR_materials_unlit",
                             "KHR_texture_transform", "KHR_materials_specular"};
    // A 1x1 PNG would need an encoder; an undecodable image exercises the fallback as well.
    doc["images"] = json::array({{{"uri", "data:image/png;base64,AAAA"}}});
    doc["textures"] = json::array({{{"source", 0}}});
    doc["materials"] = json::array({
        {{"name", "transformed"},
         {"emissiveFactor", {1, 0.5, 0}},
         {"alphaMode", "MASK"},
         {"alphaCutoff", 0.3},
         {"doubleSided", true},
         {"normalTexture", {{"index", 0}, {"scale", 0.5}}},
         {"occlusionTexture", {{"index", 0}, {"strength", 0.25}}},
         {"pbrMetallicRoughness",
          {{"baseColorFactor", {0.1, 0.2, 0.3, 0.4}},
           {"metallicFactor", 0.6},
           {"roughnessFactor", 0.7},
           {"baseColorTexture",
            {{"index", 0},
             {"extensions",
              {{"KHR_texture_transform",
                {{"offset", {0.5, 0.25}},
                 {"rotation", 1.5},
                 {"scale", {2, 3}},
                 {"texCoord", 1}}}}}}}}},
         {"extensions",
          {{"KHR_materials_emissive_strength", {{"emissiveStrength", 5.0}}},
           {"KHR_materials_specular", {{"specularFactor", 0.5}}}}}},
        {{"name", "unlit"}, {"extensions", {{"KHR_materials_unlit", json::object()}}}},
        {{"name", "skin"},
         {"extras",
          {{"shadingModel", "subsurface"},
           {"specular", 0.35},
           {"subsurfaceColor", {0.9, 0.3, 0.2}},
           {"subsurfaceOpacity", 0.4}}}},
        {{"name", "legacy"},
         {"extras",
          {{"shadingModel", "legacy"},
           {"diffuseColor", {0.5, 0.4, 0.3}},
           {"specularColor", {0.2, 0.2, 0.2}}}}},
    });
    Diagnostics diagnostics;
    auto m = loadJson(doc, diagnostics);
    ASSERT_TRUE(m) << diagnostics.toString();
    ASSERT_EQ(m->materials.size(), 4u);

    const Material& t = m->materials[0];
    EXPECT_EQ(t.baseColorFactor, (std::array<float, 4>{0.1f, 0.2f, 0.3f, 0.4f}));
    EXPECT_FLOAT_EQ(t.metallicFactor, 0.6f);
    EXPECT_FLOAT_EQ(t.roughnessFactor, 0.7f);
    EXPECT_FLOAT_EQ(t.normalScale, 0.5f);
    EXPECT_FLOAT_EQ(t.occlusionStrength, 0.25f);
    EXPECT_FLOAT_EQ(t.emissiveStrength, 5.0f);
    EXPECT_EQ(t.emissiveFactor, (std::array<float, 3>{1, 0.5f, 0}));
    EXPECT_EQ(t.alphaMode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(t.alphaCutoff, 0.3f);
    EXPECT_TRUE(t.doubleSided);
    EXPECT_FLOAT_EQ(t.specular, 0.25f) << "F0 0.04 * 0.5 = 0.08 * 0.25";
    EXPECT_EQ(t.baseColorTexture.transform.offset, (std::array<float, 2>{0.5f, 0.25f}));
    EXPECT_FLOAT_EQ(t.baseColorTexture.transform.rotation, 1.5f);
    EXPECT_EQ(t.baseColorTexture.transform.scale, (std::array<float, 2>{2, 3}));
    EXPECT_EQ(t.baseColorTexture.texCoord, 1u) << "KHR_texture_transform overrides texCoord";

    // The undecodable image became the magenta checker, and said so.
    ASSERT_EQ(m->images.size(), 1u);
    EXPECT_TRUE(m->images[0].isFallback);
    EXPECT_TRUE(diagnostics.mentions("images[0]"));
    EXPECT_EQ(m->images[0].rgba[0], 255);
    EXPECT_EQ(m->images[0].rgba[1], 0);

    EXPECT_EQ(m->materials[1].shadingModel, ShadingModel::Unlit);
    const Material& skin = m->materials[2];
    EXPECT_EQ(skin.shadingModel, ShadingModel::Subsurface);
    EXPECT_FLOAT_EQ(skin.specular, 0.35f);
    EXPECT_EQ(skin.subsurfaceColor, (std::array<float, 3>{0.9f, 0.3f, 0.2f}));
    EXPECT_FLOAT_EQ(skin.subsurfaceOpacity, 0.4f);
    const Material& legacy = m->materials[3];
    EXPECT_EQ(legacy.shadingModel, ShadingModel::Legacy);
    EXPECT_EQ(legacy.diffuseColor, (std::array<float, 3>{0.5f, 0.4f, 0.3f}));
    EXPECT_EQ(legacy.specularColor, (std::array<float, 3>{0.2f, 0.2f, 0.2f}));
}

// Issue 21: KHR_materials_anisotropy and KHR_materials_clearcoat, values and textures; values
// outside [0, 1] are clamped with a warning naming the material.
TEST(GltfFeatures, AnisotropyAndClearcoatExtensions) {
    json doc = quadDocument();
    doc["extensionsUsed"] = {"KHR_materials_anisotropy", "KHR_materials_clearcoat"};
    doc["extensionsRequired"] = {"KHR_materials_anisotropy", "KHR_materials_clearcoat"};
    doc["images"] = json::array({{{"uri", "data:image/png;base64,AAAA"}}});
    doc["textures"] = json::array({{{"source", 0}}});
    doc["materials"] = json::array({
        {{"name", "brushed"},
         {"extensions",
          {{"KHR_materials_anisotropy",
            {{"anisotropyStrength", 0.6},
             {"anisotropyRotation", 0.5},
             {"anisotropyTexture", {{"index", 0}, {"texCoord", 1}}}}}}}},
        {{"name", "paint"},
         {"extensions",
          {{"KHR_materials_clearcoat",
            {{"clearcoatFactor", 0.8},
             {"clearcoatRoughnessFactor", 0.1},
             {"clearcoatTexture", {{"index", 0}}},
             {"clearcoatRoughnessTexture", {{"index", 0}}},
             {"clearcoatNormalTexture", {{"index", 0}, {"scale", 0.5}}}}}}}},
        {{"name", "out of range"},
         {"extensions",
          {{"KHR_materials_anisotropy", {{"anisotropyStrength", 3.0}}},
           {"KHR_materials_clearcoat", {{"clearcoatFactor", -1.0}}}}}},
        {{"name", "plain"}},
    });
    Diagnostics diagnostics;
    auto m = loadJson(doc, diagnostics);
    ASSERT_TRUE(m) << diagnostics.toString();
    ASSERT_EQ(m->materials.size(), 4u);
    const Material& brushed = m->materials[0];
    EXPECT_TRUE(brushed.anisotropic());
    EXPECT_FALSE(brushed.clearCoated());
    EXPECT_FLOAT_EQ(brushed.anisotropyStrength, 0.6f);
    EXPECT_FLOAT_EQ(brushed.anisotropyRotation, 0.5f);
    EXPECT_TRUE(brushed.anisotropyTexture.present());
    EXPECT_EQ(brushed.anisotropyTexture.texCoord, 1u);
    EXPECT_EQ(brushed.anisotropyTexture.colorSpace, ColorSpace::Linear);
    const Material& paint = m->materials[1];
    EXPECT_TRUE(paint.clearCoated());
    EXPECT_FALSE(paint.anisotropic());
    EXPECT_FLOAT_EQ(paint.clearcoatFactor, 0.8f);
    EXPECT_FLOAT_EQ(paint.clearcoatRoughnessFactor, 0.1f);
    EXPECT_TRUE(paint.clearcoatTexture.present());
    EXPECT_TRUE(paint.clearcoatRoughnessTexture.present());
    EXPECT_TRUE(paint.clearcoatNormalTexture.present());
    EXPECT_FLOAT_EQ(paint.clearcoatNormalScale, 0.5f);
    const Material& clamped = m->materials[2];
    EXPECT_FLOAT_EQ(clamped.anisotropyStrength, 1.0f);
    EXPECT_FLOAT_EQ(clamped.clearcoatFactor, 0.0f);
    EXPECT_TRUE(diagnostics.mentions("materials[2]")) << diagnostics.toString();
    EXPECT_FALSE(m->materials[3].anisotropic());
    EXPECT_FALSE(m->materials[3].clearCoated());
}

// Issue 25: extras.cavity (UE4's Cavity) in [0, 1]; out of range is clamped and a non-number
// ignored, each with a warning naming the file and the material.
TEST(GltfFeatures, CavityExtraIsReadClampedAndWarned) {
    json doc = quadDocument();
    doc["materials"] = json::array({
        {{"name", "crevice"}, {"extras", {{"cavity", 0.25}}}},
        {{"name", "too bright"}, {"extras", {{"cavity", 2.5}}}},
        {{"name", "wordy"}, {"extras", {{"cavity", "deep"}}}},
        {{"name", "plain"}},
    });
    Diagnostics diagnostics;
    auto m = loadJson(doc, diagnostics, "cavity.gltf");
    ASSERT_TRUE(m) << diagnostics.toString();
    ASSERT_EQ(m->materials.size(), 4u);
    EXPECT_FLOAT_EQ(m->materials[0].cavity, 0.25f);
    EXPECT_FLOAT_EQ(m->materials[1].cavity, 1.0f);
    EXPECT_FLOAT_EQ(m->materials[2].cavity, 1.0f);
    EXPECT_FLOAT_EQ(m->materials[3].cavity, 1.0f);
    const std::string text = diagnostics.toString();
    EXPECT_FALSE(diagnostics.mentions("crevice")) << text;
    EXPECT_TRUE(diagnostics.mentions("cavity.gltf")) << text;
    EXPECT_TRUE(diagnostics.mentions("'too bright'")) << text;
    EXPECT_TRUE(diagnostics.mentions("outside [0, 1]")) << text;
    EXPECT_TRUE(diagnostics.mentions("'wordy'")) << text;
    EXPECT_TRUE(diagnostics.mentions("not a finite number")) << text;
}

TEST(GltfFeatures, CamerasMatricesStripsU8IndicesAndVertexColours) {
    json doc = quadDocument();
    testing::BinaryBuffer buffer;
    buffer.append(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0});
    buffer.append(std::vector<std::uint8_t>{0, 1, 2, 3});
    buffer.append(std::vector<std::uint8_t>{255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255});
    doc["buffers"].push_back({{"byteLength", buffer.bytes.size()}, {"uri", buffer.dataUri()}});
    doc["bufferViews"].push_back({{"buffer", 1}, {"byteOffset", 0}, {"byteLength", 48}});
    doc["bufferViews"].push_back({{"buffer", 1}, {"byteOffset", 48}, {"byteLength", 4}});
    doc["bufferViews"].push_back({{"buffer", 1}, {"byteOffset", 52}, {"byteLength", 12}});
    doc["accessors"].push_back(
        {{"bufferView", 3}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}});
    doc["accessors"].push_back(
        {{"bufferView", 4}, {"componentType", 5121}, {"count", 4}, {"type", "SCALAR"}});
    doc["accessors"].push_back({{"bufferView", 5},
                                {"componentType", 5121},
                                {"normalized", true},
                                {"count", 4},
                                {"type", "VEC3"}});
    doc["meshes"].push_back(
        {{"primitives",
          {{{"attributes", {{"POSITION", 3}, {"COLOR_0", 5}}}, {"indices", 4}, {"mode", 5}}}}});
    doc["cameras"] = json::array(
        {{{"type", "perspective"},
          {"perspective", {{"yfov", 0.9}, {"znear", 0.1}, {"zfar", 200.0}}}},
         {{"type", "orthographic"},
          {"orthographic", {{"xmag", 2.0}, {"ymag", 1.5}, {"znear", 0.0}, {"zfar", 50.0}}}}});
    // Column-major: scale 2 along X, then translate (1, 2, 3).
    doc["nodes"].push_back({{"name", "strip"},
                            {"mesh", 1},
                            {"camera", 1},
                            {"matrix", {2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 2, 3, 1}}});
    doc["nodes"][0]["children"] = {1};
    doc["nodes"][0]["camera"] = 0;
    Diagnostics diagnostics;
    auto m = loadJson(doc, diagnostics);
    ASSERT_TRUE(m) << diagnostics.toString();
    const Primitive& strip = m->meshes.at(1).primitives.at(0);
    EXPECT_EQ(strip.indices.size(), 6u);
    ASSERT_EQ(strip.colors.size(), strip.positions.size());
    EXPECT_EQ(strip.colors[0], (Float4{1, 0, 0, 1}));
    const Node& node = m->nodes.at(1);
    EXPECT_EQ(node.parent, 0);
    EXPECT_EQ(node.local.translation, (Float3{1, 2, 3}));
    EXPECT_EQ(node.local.scale, (Float3{2, 1, 1}));
    EXPECT_EQ(node.local.rotation, (Float4{0, 0, 0, 1}));
    ASSERT_EQ(m->cameras.size(), 2u);
    EXPECT_FLOAT_EQ(m->cameras[0].camera.verticalFov, 0.9f);
    EXPECT_FLOAT_EQ(m->cameras[0].camera.farPlane, 200.0f);
    EXPECT_EQ(m->cameras[1].camera.projection, Projection::Orthographic);
    EXPECT_FLOAT_EQ(m->cameras[1].camera.orthographicHalfHeight, 1.5f);
    EXPECT_EQ(m->nodes[0].camera, 0);
    EXPECT_EQ(node.camera, 1);
}

// Issue 19 (Persson 2014, GPU Pro 5, "Wire Antialiasing"): LINES / LINE_STRIP / LINE_LOOP
// primitives whose material's extras gives wireRadius become wires (index pairs, the radius in
// metres); lines without it stay skipped with a warning; a radius that is not a finite positive
// number is an error naming the file and the material's element, and its lines stay skipped.
TEST(GltfFeatures, LinePrimitivesWithWireRadiusBecomeWires) {
    json doc = quadDocument();
    doc["materials"] = json::array({
        {{"name", "plain"}},
        {{"name", "cable"}, {"extras", {{"wireRadius", 0.02}}}},
        {{"name", "inside out"}, {"extras", {{"wireRadius", -1.0}}}},
        {{"name", "wordy"}, {"extras", {{"wireRadius", "NaN"}}}},
    });
    // The quad's four corners as lines (0-1, 2-3), a strip (0-1-2-3) and a loop.
    auto lines = [](int mode, int material) {
        return json{{"attributes", {{"POSITION", 0}}}, {"mode", mode}, {"material", material}};
    };
    doc["meshes"][0]["primitives"].push_back(lines(1, 1));  // LINES
    doc["meshes"][0]["primitives"].push_back(lines(3, 1));  // LINE_STRIP
    doc["meshes"][0]["primitives"].push_back(lines(2, 1));  // LINE_LOOP
    doc["meshes"][0]["primitives"].push_back(lines(1, 0));  // no wireRadius: skipped
    doc["meshes"][0]["primitives"].push_back(lines(1, 2));  // negative: skipped
    doc["meshes"][0]["primitives"].push_back(lines(3, 3));  // not a number: skipped
    Diagnostics diagnostics;
    auto m = loadJson(doc, diagnostics, "wires.gltf");
    ASSERT_TRUE(m) << diagnostics.toString();
    const std::string text = diagnostics.toString();
    ASSERT_EQ(m->meshes[0].primitives.size(), 1u) << text;  // the quad
    ASSERT_EQ(m->meshes[0].wires.size(), 3u) << text;
    const auto& wires = m->meshes[0].wires;
    EXPECT_FLOAT_EQ(wires[0].radius, 0.02f);
    EXPECT_EQ(wires[0].material, 1);
    EXPECT_EQ(wires[0].positions.size(), 4u);
    EXPECT_EQ(wires[0].segments, (std::vector<std::uint32_t>{0, 1, 2, 3}));
    EXPECT_EQ(wires[1].segments, (std::vector<std::uint32_t>{0, 1, 1, 2, 2, 3}));
    EXPECT_EQ(wires[2].segments, (std::vector<std::uint32_t>{0, 1, 1, 2, 2, 3, 3, 0}));
    EXPECT_FLOAT_EQ(m->materials[2].wireRadius, 0.0f);
    EXPECT_FLOAT_EQ(m->materials[3].wireRadius, 0.0f);
    EXPECT_TRUE(diagnostics.mentions("wires.gltf")) << text;
    EXPECT_TRUE(diagnostics.mentions("materials[2].extras.wireRadius")) << text;
    EXPECT_TRUE(diagnostics.mentions("'inside out'")) << text;
    EXPECT_TRUE(diagnostics.mentions("materials[3].extras.wireRadius")) << text;
    EXPECT_TRUE(diagnostics.mentions("'wordy'")) << text;
    EXPECT_TRUE(diagnostics.mentions("meshes[0].primitives[4]")) << text;  // plain lines
    EXPECT_TRUE(diagnostics.mentions("lines")) << text;
    EXPECT_FALSE(diagnostics.mentions("meshes[0].primitives[1]")) << text;
}

// Issue 19 (Martin et al. 2014, GPU Pro 5, "TressFX: Advanced Real-Time Hair Rendering"): LINES /
// LINE_STRIP primitives whose material's extras has a `hair` object become hair strands
// (Mesh::hair) with each position's place from root (0) to tip (1); the style's keys are read,
// missing ones keep their defaults (a missing tip radius: the root's), and a wrong key is an error
// naming materials[i].extras.hair.<key>, the material making no hair.
TEST(GltfFeatures, LinePrimitivesWithHairExtrasBecomeStrands) {
    json doc = quadDocument();
    doc["materials"] = json::array({
        {{"name", "fur"},
         {"extras",
          {{"hair",
            {{"rootRadius", 0.002},
             {"tipRadius", 0.0005},
             {"color", {0.5, 0.25, 0.125}},
             {"primaryShift", 0.2},
             {"secondaryShift", -0.3},
             {"primaryExponent", 60.0},
             {"secondaryExponent", 12.0}}}}}},
        {{"name", "plain hair"}, {"extras", {{"hair", {{"rootRadius", 0.001}}}}}},
        {{"name", "bad radius"}, {"extras", {{"hair", {{"tipRadius", -1.0}}}}}},
        {{"name", "bad colour"}, {"extras", {{"hair", {{"color", {2.0, 0.0, 0.0}}}}}}},
        {{"name", "bad exponent"}, {"extras", {{"hair", {{"primaryExponent", "sharp"}}}}}},
        {{"name", "not an object"}, {"extras", {{"hair", 3}}}},
    });
    auto lines = [](int mode, int material) {
        return json{{"attributes", {{"POSITION", 0}}}, {"mode", mode}, {"material", material}};
    };
    doc["meshes"][0]["primitives"].push_back(lines(3, 0));  // LINE_STRIP: one strand
    doc["meshes"][0]["primitives"].push_back(lines(1, 1));  // LINES: two strands 0-1, 2-3
    for (int bad = 2; bad < 6; ++bad)
        doc["meshes"][0]["primitives"].push_back(lines(3, bad));
    Diagnostics diagnostics;
    auto m = loadJson(doc, diagnostics, "hair.gltf");
    ASSERT_TRUE(m) << diagnostics.toString();
    const std::string text = diagnostics.toString();
    ASSERT_EQ(m->meshes[0].hair.size(), 2u) << text;
    ASSERT_TRUE(m->materials[0].hair);
    const HairStyle& style = *m->materials[0].hair;
    EXPECT_FLOAT_EQ(style.rootRadius, 0.002f);
    EXPECT_FLOAT_EQ(style.tipRadius, 0.0005f);
    EXPECT_FLOAT_EQ(style.color[1], 0.25f);
    EXPECT_FLOAT_EQ(style.primaryShift, 0.2f);
    EXPECT_FLOAT_EQ(style.secondaryShift, -0.3f);
    EXPECT_FLOAT_EQ(style.primaryExponent, 60.0f);
    EXPECT_FLOAT_EQ(style.secondaryExponent, 12.0f);
    ASSERT_TRUE(m->materials[1].hair);
    EXPECT_FLOAT_EQ(m->materials[1].hair->tipRadius, 0.001f);  // the root's
    for (int bad = 2; bad < 6; ++bad)
        EXPECT_FALSE(m->materials[size_t(bad)].hair) << bad;
    const Hair& strip = m->meshes[0].hair[0];
    EXPECT_EQ(strip.segments, (std::vector<std::uint32_t>{0, 1, 1, 2, 2, 3}));
    ASSERT_EQ(strip.rootToTip.size(), 4u);
    EXPECT_FLOAT_EQ(strip.rootToTip[0], 0.0f);
    EXPECT_FLOAT_EQ(strip.rootToTip[3], 1.0f);
    EXPECT_GT(strip.rootToTip[1], 0.0f);
    EXPECT_LT(strip.rootToTip[1], strip.rootToTip[2]);
    const Hair& pairs = m->meshes[0].hair[1];
    EXPECT_EQ(pairs.material, 1);
    EXPECT_EQ(pairs.rootToTip, (std::vector<float>{0.0f, 1.0f, 0.0f, 1.0f}));
    EXPECT_TRUE(diagnostics.mentions("hair.gltf")) << text;
    EXPECT_TRUE(diagnostics.mentions("materials[2].extras.hair.tipRadius")) << text;
    EXPECT_TRUE(diagnostics.mentions("materials[3].extras.hair.color")) << text;
    EXPECT_TRUE(diagnostics.mentions("materials[4].extras.hair.primaryExponent")) << text;
    EXPECT_TRUE(diagnostics.mentions("materials[5].extras.hair")) << text;
    EXPECT_TRUE(diagnostics.mentions("'bad radius'")) << text;
}

// Issue 44: every key of extras.hair is optional, yet `"hair": {}` made no hair: tinygltf's
// value tree drops empty objects. An empty object is hair in the default style, alone or
// beside other extras.
TEST(GltfFeatures, AnEmptyHairExtraIsHairInTheDefaultStyle) {
    json doc = quadDocument();
    doc["materials"] = json::array({
        {{"name", "alone"}, {"extras", {{"hair", json::object()}}}},
        {{"name", "beside"}, {"extras", {{"hair", json::object()}, {"specular", 0.25}}}},
        {{"name", "none"}, {"extras", {{"specular", 0.25}}}},
    });
    for (int material = 0; material < 3; ++material) {
        doc["meshes"][0]["primitives"].push_back(
            {{"attributes", {{"POSITION", 0}}}, {"mode", 3}, {"material", material}});
    }
    Diagnostics diagnostics;
    auto m = loadJson(doc, diagnostics, "empty_hair.gltf");
    ASSERT_TRUE(m) << diagnostics.toString();
    const HairStyle defaults;
    for (int material = 0; material < 2; ++material) {
        ASSERT_TRUE(m->materials[size_t(material)].hair) << material;
        EXPECT_EQ(m->materials[size_t(material)].hair->rootRadius, defaults.rootRadius);
    }
    EXPECT_FLOAT_EQ(m->materials[1].specular, 0.25f);
    EXPECT_FALSE(m->materials[2].hair);
    EXPECT_EQ(m->meshes[0].hair.size(), 2u) << diagnostics.toString();
}

// Hair generated on a mesh (scene files, the demo): the same seed gives the same strands, a
// different seed others; every root lies on the surface and every strand has its length.
TEST(GltfFeatures, GeneratedHairIsDeterministicAndRootedOnTheSurface) {
    const Primitive sphere = makeSphere(0.5f, 16, 8);
    const Hair a = generateHair(sphere, 200, 0.1f, 7, 4);
    const Hair b = generateHair(sphere, 200, 0.1f, 7, 4);
    const Hair c = generateHair(sphere, 200, 0.1f, 8, 4);
    ASSERT_EQ(a.positions.size(), 800u);
    ASSERT_EQ(a.segments.size(), 200u * 3u * 2u);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_NE(a.positions, c.positions);
    for (std::size_t s = 0; s < 200; ++s) {
        const auto& root = a.positions[4 * s];
        const float r = std::sqrt(root[0] * root[0] + root[1] * root[1] + root[2] * root[2]);
        EXPECT_NEAR(r, 0.5f, 0.02f) << s;  // on the (faceted) sphere
        float length = 0.0f;
        for (std::size_t k = 1; k < 4; ++k) {
            const auto& p = a.positions[4 * s + k - 1];
            const auto& q = a.positions[4 * s + k];
            length += std::hypot(q[0] - p[0], q[1] - p[1], q[2] - p[2]);
        }
        EXPECT_NEAR(length, 0.1f, 1e-5f) << s;
        EXPECT_FLOAT_EQ(a.rootToTip[4 * s], 0.0f);
        EXPECT_FLOAT_EQ(a.rootToTip[4 * s + 3], 1.0f);
    }
}

}  // namespace
}  // namespace candela::content

namespace candela::content {
namespace {

// Issue 46: a node's extras.rigidBody and extras.collider read as a scene file spells them,
// and become components when the model is instantiated.
TEST(GltfFeatures, NodeExtrasDescribeRigidBodiesAndColliders) {
    json doc = testing::quadDocument();
    doc["nodes"][0]["extras"] = {
        {"rigidBody", {{"type", "dynamic"}, {"mass", 2.0}, {"restitution", 0.5}}},
        {"collider", {{"shape", "convexHull"}}}};
    doc["nodes"].push_back(
        {{"name", "ground"},
         {"extras", {{"collider", {{"shape", "box"}, {"halfExtents", {5, 0.1, 5}}}}}}});
    doc["scenes"][0]["nodes"] = {0, 1};
    Diagnostics diagnostics;
    auto m = loadJson(doc, diagnostics);
    ASSERT_TRUE(m) << diagnostics.toString();
    EXPECT_TRUE(diagnostics.messages.empty()) << diagnostics.toString();
    ASSERT_TRUE(m->nodes[0].rigidBody && m->nodes[0].collider);
    EXPECT_EQ(m->nodes[0].rigidBody->mass, 2.0f);
    EXPECT_EQ(m->nodes[0].collider->shape, ColliderShape::ConvexHull);
    EXPECT_FALSE(m->nodes[1].rigidBody);
    ASSERT_TRUE(m->nodes[1].collider && m->nodes[1].collider->halfExtents);
    EXPECT_EQ(m->nodes[1].collider->halfExtents->x, 5.0f);
    ecs::Registry registry;
    const std::vector<ecs::Entity> made = instantiateModel(registry, *m);
    ASSERT_EQ(made.size(), 2u);
    EXPECT_TRUE(registry.has<RigidBody>(made[0]));
    EXPECT_TRUE(registry.has<Collider>(made[0]));
    EXPECT_TRUE(registry.has<Collider>(made[1]));
    EXPECT_FALSE(registry.has<RigidBody>(made[1]));
}

TEST(GltfFeatures, BadPhysicsExtrasNameTheNodeAndKey) {
    json doc = testing::quadDocument();
    doc["nodes"][0]["extras"] = {{"collider", {{"shape", "sphere"}, {"radius", -1}}},
                                 {"rigidBody", {{"mass", -5}}}};
    Diagnostics diagnostics;
    auto m = loadJson(doc, diagnostics);
    ASSERT_TRUE(m) << diagnostics.toString();
    const std::string text = diagnostics.toString();
    EXPECT_NE(text.find("nodes[0].extras/collider/radius"), std::string::npos) << text;
    EXPECT_NE(text.find("nodes[0].extras/rigidBody/mass"), std::string::npos) << text;
    EXPECT_FALSE(m->nodes[0].collider) << "a shapeless collider is left out";
    ASSERT_TRUE(m->nodes[0].rigidBody);
    EXPECT_EQ(m->nodes[0].rigidBody->mass, 1.0f) << "clamped";
}

}  // namespace
}  // namespace candela::content
