// Material layers (issue 21, Karis 2013, "Real Shading in Unreal Engine 4", "Material Layering") on
// the real renderer: a layered material renders as the blend of its layers. Three spheres take the
// mask 0, 1 and 0.5 from their vertex colour; the same spheres drawn with the base alone, the layer
// alone and the parameters averaged by hand must give the same frame (the blend happens in the
// G-buffer, before lighting, so even the non-linear lighting of metallic and roughness matches).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "ibl_test_support.h"
#include "test_scene.h"

using namespace candela::render;
using namespace candela::render::test;
using candela::content::Material;
using candela::content::MaterialLayer;

namespace {

// Painted metal (base) and rust (the layer): different in every blended parameter.
MaterialLayer paint() {
    MaterialLayer l;
    l.name = "paint";
    l.baseColorFactor = {0.1f, 0.3f, 0.8f, 1.0f};
    l.metallicFactor = 1.0f;
    l.roughnessFactor = 0.25f;
    l.specular = 0.5f;
    return l;
}

MaterialLayer rust() {
    MaterialLayer l;
    l.name = "rust";
    l.baseColorFactor = {0.45f, 0.15f, 0.05f, 1.0f};
    l.metallicFactor = 0.0f;
    l.roughnessFactor = 0.9f;
    l.specular = 0.3f;
    return l;
}

// A plain material with a layer's parameters (what "the layer rendered alone" means).
Material single(const MaterialLayer& l) {
    Material m;
    m.baseColorFactor = l.baseColorFactor;
    m.metallicFactor = l.metallicFactor;
    m.roughnessFactor = l.roughnessFactor;
    m.specular = l.specular;
    return m;
}

MaterialLayer halfway(const MaterialLayer& a, const MaterialLayer& b) {
    MaterialLayer h = a;
    for (size_t c = 0; c < 3; ++c)
        h.baseColorFactor[c] = 0.5f * (a.baseColorFactor[c] + b.baseColorFactor[c]);
    h.metallicFactor = 0.5f * (a.metallicFactor + b.metallicFactor);
    h.roughnessFactor = 0.5f * (a.roughnessFactor + b.roughnessFactor);
    h.specular = 0.5f * (a.specular + b.specular);
    return h;
}

// Four spheres in a row, lit by the sun, each with its own material and vertex colour
// `colours[i]` (the mask of a vertex-colour-masked material).
TestScene fourSpheres(const Material (&materials)[4], const glm::vec4 (&colours)[4]) {
    TestScene scene;
    scene.width = 128;
    scene.height = 128;
    for (int i = 0; i < 4; ++i) {
        candela::content::Primitive sphere = candela::content::makeSphere(0.22f, 32, 16);
        const glm::vec4 c = colours[i];
        sphere.colors.assign(sphere.positions.size(), {c.r, c.g, c.b, c.a});
        scene.add(std::move(sphere), materials[i],
                  glm::translate(glm::mat4(1.0f), glm::vec3(0.5f * float(i) - 0.75f, 0.0f, 0.0f)));
    }
    LightInstance sun;
    sun.light.type = candela::content::LightType::Directional;
    sun.light.lux = 3.0f;
    sun.direction = glm::normalize(glm::vec3(-0.3f, -0.6f, -1.0f));
    scene.lights.push_back(sun);
    scene.lookAt({0.0f, 0.0f, 2.2f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
    return scene;
}

const glm::vec4 kWhite[4] = {glm::vec4(1.0f), glm::vec4(1.0f), glm::vec4(1.0f), glm::vec4(1.0f)};

double meanAbsDifference(const CapturedFrame& a, const CapturedFrame& b, float* largest) {
    double sum = 0.0;
    *largest = 0.0f;
    for (size_t i = 0; i < a.hdrRgb.size(); ++i) {
        const float d = std::fabs(a.hdrRgb[i] - b.hdrRgb[i]);
        sum += d;
        *largest = std::max(*largest, d);
    }
    return sum / double(a.hdrRgb.size());
}

}  // namespace

// Spheres 0-2: paint under rust, masks 0, 1 and 0.5. Sphere 3: three layers over a base take
// the mask's R, G and B; with (0, 0, 1) only the third shows.
TEST(MaterialLayers, BlendMatchesEachLayerAloneAtMask0And1AndTheirMeanAtHalf) {
    GpuContext& context = sharedContext();
    Material twoLayers;
    twoLayers.layering.layers = {paint(), rust()};
    twoLayers.layering.maskSource = candela::content::LayerMaskSource::VertexColor;
    MaterialLayer green = rust();
    green.name = "green";
    green.baseColorFactor = {0.1f, 0.7f, 0.1f, 1.0f};
    green.roughnessFactor = 0.6f;
    Material fourLayers = twoLayers;
    fourLayers.layering.layers = {paint(), rust(), paint(), green};
    const Material layered[4] = {twoLayers, twoLayers, twoLayers, fourLayers};
    const CapturedFrame blended =
        fourSpheres(layered, {glm::vec4(0, 0, 0, 1), glm::vec4(1, 0, 0, 1),
                              glm::vec4(0.5f, 0, 0, 1), glm::vec4(0, 0, 1, 1)})
            .render(context);

    // The vertex colour is the mask there, not a tint: the references get white.
    const Material alone[4] = {single(paint()), single(rust()), single(halfway(paint(), rust())),
                               single(green)};
    const CapturedFrame expected = fourSpheres(alone, kWhite).render(context);

    ASSERT_EQ(blended.hdrRgb.size(), expected.hdrRgb.size());
    float largest = 0.0f;
    const double mean = meanAbsDifference(blended, expected, &largest);
    // Same G-buffer values up to the 8-bit base colour and 16-bit roughness/metallic rounding.
    EXPECT_LT(largest, 2e-2f) << "mean " << mean;
    EXPECT_LT(mean, 1e-4);

    // The comparison can fail: paint and rust differ clearly where their spheres are.
    const float* paintPixel = hdrPixel(blended, 21, 64);
    const float* rustPixel = hdrPixel(blended, 50, 64);
    EXPECT_GT(std::fabs(paintPixel[2] - rustPixel[2]) + std::fabs(paintPixel[0] - rustPixel[0]),
              0.05f);
}
