// The Khronos sample models in the shared assets load without errors and carry the data
// their authors intended.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "candela/content/gltf_loader.h"
#include "candela/content/tangent_generation.h"

namespace candela::content {
namespace {

std::filesystem::path model(const std::string& name) {
    return std::filesystem::path(CANDELA_SHARED_ASSETS) / "models" / name / (name + ".glb");
}

Model loadClean(const std::string& name) {
    Diagnostics diagnostics;
    auto loaded = loadGltf(model(name), diagnostics);
    EXPECT_TRUE(loaded) << diagnostics.toString();
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.toString();
    return loaded ? std::move(*loaded) : Model{};
}

float length3(const Float3& v) {
    return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

TEST(GltfSampleModels, DamagedHelmetHasEveryTextureSlotWithTheRightColorSpace) {
    Model m = loadClean("DamagedHelmet");
    ASSERT_EQ(m.meshes.size(), 1u);
    ASSERT_EQ(m.meshes[0].primitives.size(), 1u);
    const Primitive& p = m.meshes[0].primitives[0];
    EXPECT_EQ(p.positions.size(), 14560u);
    EXPECT_EQ(p.indices.size(), 46356u);
    EXPECT_FALSE(p.normalsGenerated);
    EXPECT_TRUE(p.tangentsGenerated) << "the helmet has a normal map but no TANGENT";
    ASSERT_EQ(p.tangents.size(), p.positions.size());
    for (std::uint32_t index : p.indices)
        ASSERT_LT(index, p.positions.size());

    ASSERT_EQ(m.materials.size(), 1u);
    const Material& mat = m.materials[0];
    EXPECT_TRUE(mat.baseColorTexture.present());
    EXPECT_TRUE(mat.metallicRoughnessTexture.present());
    EXPECT_TRUE(mat.normalTexture.present());
    EXPECT_TRUE(mat.occlusionTexture.present());
    EXPECT_TRUE(mat.emissiveTexture.present());
    EXPECT_EQ(mat.baseColorTexture.colorSpace, ColorSpace::Srgb);
    EXPECT_EQ(mat.emissiveTexture.colorSpace, ColorSpace::Srgb);
    EXPECT_EQ(mat.metallicRoughnessTexture.colorSpace, ColorSpace::Linear);
    EXPECT_EQ(mat.normalTexture.colorSpace, ColorSpace::Linear);
    EXPECT_EQ(mat.occlusionTexture.colorSpace, ColorSpace::Linear);
    EXPECT_EQ(mat.emissiveFactor, (std::array<float, 3>{1, 1, 1}));
    ASSERT_EQ(m.images.size(), 5u);
    for (const Rgba8Image& image : m.images) {
        EXPECT_EQ(image.width, 2048u);
        EXPECT_EQ(image.rgba.size(), 2048u * 2048u * 4u);
        EXPECT_FALSE(image.isFallback);
    }
    // The node carries a 90 degree rotation about X (the helmet is authored Z-up).
    ASSERT_EQ(m.nodes.size(), 1u);
    const Float4& q = m.nodes[0].local.rotation;
    EXPECT_NEAR(std::fabs(q[0]), std::sqrt(0.5f), 1e-5f);
    EXPECT_NEAR(std::fabs(q[3]), std::sqrt(0.5f), 1e-5f);
}

TEST(GltfSampleModels, GeneratedTangentsAreUnitAndPerpendicularToNormals) {
    Model m = loadClean("DamagedHelmet");
    const Primitive& p = m.meshes[0].primitives[0];
    for (std::size_t v = 0; v < p.positions.size(); ++v) {
        const Float4& t = p.tangents[v];
        const Float3 t3{t[0], t[1], t[2]};
        ASSERT_NEAR(length3(t3), 1.0f, 1e-4f) << v;
        const Float3& n = p.normals[v];
        ASSERT_NEAR(n[0] * t[0] + n[1] * t[1] + n[2] * t[2], 0.0f, 1e-4f) << v;
        ASSERT_TRUE(t[3] == 1.0f || t[3] == -1.0f) << v;
    }
}

TEST(GltfSampleModels, GeneratedTangentsMatchTheTangentsAuthoredInAlphaBlendModeTest) {
    // This asset ships MikkTSpace tangents; regenerating them must reproduce them.
    Model m = loadClean("AlphaBlendModeTest");
    std::size_t compared = 0;
    for (const Mesh& mesh : m.meshes) {
        for (Primitive p : mesh.primitives) {
            ASSERT_FALSE(p.tangentsGenerated);
            const std::vector<Float4> authored = p.tangents;
            p.tangents.clear();
            generateTangents(p, 0);
            ASSERT_EQ(p.tangents.size(), authored.size()) << "no split needed here";
            for (std::size_t v = 0; v < authored.size(); ++v) {
                const Float4& a = authored[v];
                const Float4& g = p.tangents[v];
                EXPECT_GT(a[0] * g[0] + a[1] * g[1] + a[2] * g[2], 0.999f) << v;
                EXPECT_EQ(a[3], g[3]) << "handedness of vertex " << v;
                ++compared;
            }
        }
    }
    EXPECT_GT(compared, 100u);
}

TEST(GltfSampleModels, AlphaBlendModeTestHasEachAlphaModeAndCutoff) {
    Model m = loadClean("AlphaBlendModeTest");
    std::map<std::string, const Material*> byName;
    for (const Material& mat : m.materials)
        byName[mat.name] = &mat;
    ASSERT_TRUE(byName.count("MatOpaque") && byName.count("MatBlend") &&
                byName.count("MatCutoff25") && byName.count("MatCutoff75") &&
                byName.count("MatCutoffDefault"));
    EXPECT_EQ(byName["MatOpaque"]->alphaMode, AlphaMode::Opaque);
    EXPECT_EQ(byName["MatBlend"]->alphaMode, AlphaMode::Blend);
    EXPECT_EQ(byName["MatCutoff25"]->alphaMode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(byName["MatCutoff25"]->alphaCutoff, 0.25f);
    EXPECT_FLOAT_EQ(byName["MatCutoff75"]->alphaCutoff, 0.75f);
    EXPECT_FLOAT_EQ(byName["MatCutoffDefault"]->alphaCutoff, 0.5f);
    EXPECT_TRUE(byName["MatBlend"]->doubleSided);
}

TEST(GltfSampleModels, TextureSettingsTestHasEveryWrapModeAndNearestFiltering) {
    Model m = loadClean("TextureSettingsTest");
    std::set<std::pair<Wrap, Wrap>> wraps;
    for (const Texture& t : m.textures)
        wraps.insert({t.sampler.wrapS, t.sampler.wrapT});
    EXPECT_TRUE(wraps.count({Wrap::MirroredRepeat, Wrap::Repeat}));
    EXPECT_TRUE(wraps.count({Wrap::Repeat, Wrap::MirroredRepeat}));
    EXPECT_TRUE(wraps.count({Wrap::ClampToEdge, Wrap::Repeat}));
    EXPECT_TRUE(wraps.count({Wrap::Repeat, Wrap::ClampToEdge}));
    std::size_t doubleSided = 0;
    for (const Material& mat : m.materials)
        doubleSided += mat.doubleSided ? 1 : 0;
    EXPECT_EQ(doubleSided, 1u);
}

TEST(GltfSampleModels, MetalRoughSpheresSpanTheFactorGrid) {
    Model m = loadClean("MetalRoughSpheresNoTextures");
    std::set<float> metallic;
    std::set<float> roughness;
    for (const Material& mat : m.materials) {
        metallic.insert(mat.metallicFactor);
        roughness.insert(mat.roughnessFactor);
        EXPECT_FALSE(mat.baseColorTexture.present());
    }
    EXPECT_GE(metallic.size(), 5u);
    EXPECT_GE(roughness.size(), 5u);
    EXPECT_EQ(*metallic.begin(), 0.0f);
    EXPECT_EQ(*metallic.rbegin(), 1.0f);
}

TEST(GltfSampleModels, BoxHasAHierarchyAndBoxTexturedADecodedTexture) {
    Model box = loadClean("Box");
    ASSERT_EQ(box.nodes.size(), 2u);
    ASSERT_EQ(box.rootNodes.size(), 1u);
    const Node& root = box.nodes[static_cast<std::size_t>(box.rootNodes[0])];
    ASSERT_EQ(root.children.size(), 1u);
    EXPECT_EQ(box.nodes[static_cast<std::size_t>(root.children[0])].parent, box.rootNodes[0]);
    EXPECT_EQ(box.meshes[0].primitives[0].boundsMin, (Float3{-0.5f, -0.5f, -0.5f}));
    EXPECT_EQ(box.meshes[0].primitives[0].boundsMax, (Float3{0.5f, 0.5f, 0.5f}));

    Model textured = loadClean("BoxTextured");
    ASSERT_EQ(textured.images.size(), 1u);
    const Rgba8Image& image = textured.images[0];
    EXPECT_EQ(image.width, 256u);
    EXPECT_EQ(image.height, 256u);
    std::set<std::uint32_t> colours;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        colours.insert(image.rgba[i] | image.rgba[i + 1] << 8 | image.rgba[i + 2] << 16);
    }
    EXPECT_GT(colours.size(), 2u) << "a decoded logo, not a flat colour";
    EXPECT_EQ(textured.materials[0].baseColorTexture.colorSpace, ColorSpace::Srgb);
}

// Issue 21: the Khronos test models of the two extensions load with their grids intact.
TEST(GltfSampleModels, AnisotropyStrengthTestHasItsStrengthGrid) {
    Model m = loadClean("AnisotropyStrengthTest");
    std::set<float> strengths;
    for (const Material& mat : m.materials)
        strengths.insert(mat.anisotropyStrength);
    EXPECT_EQ(strengths.size(), 7u) << "strength 0 to 1 in sixths";
    EXPECT_EQ(*strengths.begin(), 0.0f);
    EXPECT_EQ(*strengths.rbegin(), 1.0f);
}

TEST(GltfSampleModels, ClearCoatTestHasFactorsTexturesAndCoatNormals) {
    Model m = loadClean("ClearCoatTest");
    int coated = 0, coatTextures = 0, coatNormals = 0, coatRoughnessTextures = 0;
    for (const Material& mat : m.materials) {
        coated += mat.clearCoated();
        coatTextures += mat.clearcoatTexture.present();
        coatNormals += mat.clearcoatNormalTexture.present();
        coatRoughnessTextures += mat.clearcoatRoughnessTexture.present();
    }
    EXPECT_GE(coated, 5);
    EXPECT_GE(coatTextures, 1);
    EXPECT_GE(coatNormals, 1);
    EXPECT_GE(coatRoughnessTextures, 1);
}

}  // namespace
}  // namespace candela::content
