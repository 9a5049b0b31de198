// KHR_materials_specular textures fold into the engine's `specular` input per texel:
// specular = material specular * specularTexture.a * max(specularColorFactor / max(factor) *
// specularColorTexture.rgb). Each textured material must render exactly like an untextured one
// whose `specular` is that product (the G-buffer stores both at the same 8 bits).
#include <gtest/gtest.h>

#include "test_scene.h"

using namespace candela::render;
using namespace candela::render::test;
using candela::content::ColorSpace;
using candela::content::Material;
using candela::content::TextureRef;

namespace {

// A glossy floor whose specular highlight fills the middle of the view.
TestScene highlightScene(const Material& material) {
    TestScene scene;
    scene.width = 64;
    scene.height = 64;
    scene.add(candela::content::makePlane(3.0f), material);
    scene.lookAt({0.0f, 1.5f, 2.5f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
    scene.lights.push_back(pointLight({0.0f, 1.5f, -2.5f}, 3000.0f, 20.0f));
    return scene;
}

Material glossy(float specular) {
    Material m = lambertWhite();
    m.baseColorFactor = {0.2f, 0.2f, 0.2f, 1.0f};
    m.roughnessFactor = 0.3f;
    m.specular = specular;
    return m;
}

// A 1x1 texture added to the scene's model.
TextureRef solidTexture(TestScene& scene, std::array<uint8_t, 4> rgba, ColorSpace space) {
    candela::content::Rgba8Image image;
    image.width = 1;
    image.height = 1;
    image.rgba.assign(rgba.begin(), rgba.end());
    scene.model.images.push_back(image);
    candela::content::Texture texture;
    texture.image = int32_t(scene.model.images.size() - 1);
    scene.model.textures.push_back(texture);
    TextureRef ref;
    ref.texture = int32_t(scene.model.textures.size() - 1);
    ref.colorSpace = space;
    return ref;
}

CapturedFrame renderTextured(GpuContext& context, Material material,
                             std::array<uint8_t, 4> specularTexel,
                             std::array<uint8_t, 4> specularColorTexel) {
    TestScene scene = highlightScene(material);
    scene.model.materials[0].specularTexture =
        solidTexture(scene, specularTexel, ColorSpace::Linear);
    scene.model.materials[0].specularColorTexture =
        solidTexture(scene, specularColorTexel, ColorSpace::Srgb);
    return scene.render(context);
}

}  // namespace

TEST(SpecularTextures, ScaleTheEngineSpecularPerTexel) {
    GpuContext context(requiredValidation());
    CapturedFrame untextured = highlightScene(glossy(0.5f)).render(context);
    CapturedFrame noSpecular = highlightScene(glossy(0.0f)).render(context);
    ASSERT_NE(untextured.hdrRgb, noSpecular.hdrRgb) << "the scene must show a highlight";

    // White textures change nothing.
    EXPECT_EQ(
        renderTextured(context, glossy(0.5f), {255, 255, 255, 255}, {255, 255, 255, 255}).hdrRgb,
        untextured.hdrRgb);
    // specularTexture.a = 0, or a black specular colour: no dielectric reflection.
    EXPECT_EQ(
        renderTextured(context, glossy(0.5f), {255, 255, 255, 0}, {255, 255, 255, 255}).hdrRgb,
        noSpecular.hdrRgb);
    EXPECT_EQ(renderTextured(context, glossy(0.5f), {255, 255, 255, 255}, {0, 0, 0, 255}).hdrRgb,
              noSpecular.hdrRgb);
    // Partial alpha with a coloured factor: 0.5 * (128 / 255) * max(1, 0.5, 0.25) / 1 (the
    // texture's rgb is ignored for specularTexture; only A is the factor).
    Material coloured = glossy(0.5f);
    coloured.specularColorFactor = {1.0f, 0.5f, 0.25f};
    CapturedFrame half = renderTextured(context, coloured, {0, 0, 0, 128}, {255, 255, 255, 255});
    EXPECT_EQ(half.hdrRgb, highlightScene(glossy(0.5f * 128.0f / 255.0f)).render(context).hdrRgb);
    // The colour texture's largest channel after the factor: max(1 * 0, 0.5 * 1, 0.25 * 1).
    CapturedFrame green =
        renderTextured(context, coloured, {255, 255, 255, 255}, {0, 255, 255, 255});
    EXPECT_EQ(green.hdrRgb, highlightScene(glossy(0.25f)).render(context).hdrRgb);
    EXPECT_EQ(context.validationMessages(), 0u);
}
