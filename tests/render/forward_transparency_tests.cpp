// Forward transparency pass (glTF alphaMode BLEND): straight-alpha "over" compositing onto the
// deferred result, back-to-front order per draw, the same lights in clustered and brute-force
// culling (also where the blended surface has no opaque surface in its clusters), and the pass
// recorded only when a frame has blended draws.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "test_scene.h"

using namespace candela::render;
using namespace candela::render::test;
using candela::content::AlphaMode;
using candela::content::Material;
using candela::content::ShadingModel;

namespace {

constexpr uint32_t kSize = 64;

// Primitives seen from 5 m above the origin looking down (-Y), so planes at different
// heights stack in depth; draw order is given explicitly.
struct StackScene {
    candela::content::Model model;
    std::vector<glm::mat4> worlds;
    std::vector<LightInstance> lights;
    CameraView camera;

    StackScene() {
        camera.view =
            glm::lookAt(glm::vec3(0.0f, 5.0f, 0.0f), glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f));
        camera.projection = reverseZPerspective(glm::radians(60.0f), 1.0f, 0.05f);
        camera.position = {0.0f, 5.0f, 0.0f};
        camera.nearPlane = 0.05f;
        camera.farPlane = 200.0f;
    }

    // A horizontal square of half size `halfExtent` at height y, facing up.
    uint32_t addPlane(float halfExtent, float y, const Material& material) {
        candela::content::Primitive p = candela::content::makePlane(halfExtent);
        p.material = int32_t(model.materials.size());
        model.materials.push_back(material);
        candela::content::Mesh mesh;
        mesh.primitives.push_back(std::move(p));
        model.meshes.push_back(std::move(mesh));
        worlds.push_back(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, y, 0.0f)));
        return uint32_t(worlds.size() - 1);
    }

    CapturedFrame render(GpuContext& context, const std::vector<uint32_t>& order,
                         const RendererOptions& options = {},
                         std::vector<std::string>* features = nullptr) const {
        SceneResources resources(context);
        const UploadedModel& uploaded = resources.addModel(model);
        std::vector<DrawItem> draws;
        for (uint32_t m : order) {
            draws.push_back(
                {uploaded.firstPrimitiveOfMesh[m], uploaded.firstMaterial + m, worlds[m]});
        }
        FrameInputs inputs;
        inputs.scene.camera = camera;
        inputs.scene.draws = draws;
        inputs.scene.lights = lights;
        Renderer renderer(context, kSize, kSize, options);
        FrameSubmitter submitter(context);
        FrameReadback readback(context, kSize, kSize);
        VkCommandBuffer cmd = renderer.recordFrame(submitter, inputs, &resources);
        readback.recordCopy(cmd, renderer);
        submitter.submit();
        submitter.waitIdle();
        if (features) *features = renderer.features();
        return readback.read();
    }
};

Material lit(const std::array<float, 4>& baseColor, AlphaMode mode) {
    Material m = lambertWhite();
    m.baseColorFactor = baseColor;
    m.alphaMode = mode;
    m.specular = 0.5f;  // a highlight too, so the specular path is compared as well
    m.roughnessFactor = 0.5f;
    return m;
}

Material unlitEmissive(const std::array<float, 3>& radiance, float alpha) {
    Material m;
    m.shadingModel = ShadingModel::Unlit;
    m.emissiveFactor = radiance;
    m.baseColorFactor = {1.0f, 1.0f, 1.0f, alpha};
    m.alphaMode = AlphaMode::Blend;
    return m;
}

double relativeDifference(const float* a, const float* b) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) {
        double scale = std::max({std::abs(double(a[c])), std::abs(double(b[c])), 1e-3});
        worst = std::max(worst, std::abs(double(a[c]) - double(b[c])) / scale);
    }
    return worst;
}

bool hasFeature(const std::vector<std::string>& features, const std::string& name) {
    return std::find(features.begin(), features.end(), name) != features.end();
}

}  // namespace

// Over a lit floor, a lit blended square with alpha 0.4 gives 0.4 * (the square drawn opaque)
// + 0.6 * (the floor alone) at every pixel, and leaves pixels outside it untouched.
TEST(ForwardTransparency, BlendsStraightAlphaOverTheDeferredResult) {
    GpuContext context(requiredValidation());
    const float alpha = 0.4f;
    StackScene floorOnly, opaque, blended;
    for (StackScene* s : {&floorOnly, &opaque, &blended}) {
        s->addPlane(20.0f, 0.0f, lit({1.0f, 1.0f, 1.0f, 1.0f}, AlphaMode::Opaque));
        s->lights.push_back(pointLight({0.3f, 3.0f, 0.2f}, 4000.0f, 30.0f));
    }
    opaque.addPlane(1.0f, 1.0f, lit({1.0f, 0.0f, 0.0f, alpha}, AlphaMode::Opaque));
    blended.addPlane(1.0f, 1.0f, lit({1.0f, 0.0f, 0.0f, alpha}, AlphaMode::Blend));
    CapturedFrame back = floorOnly.render(context, {0});
    CapturedFrame front = opaque.render(context, {0, 1});
    std::vector<std::string> features;
    CapturedFrame mixed = blended.render(context, {0, 1}, {}, &features);
    EXPECT_TRUE(hasFeature(features, "forward_transparency"));

    size_t covered = 0;
    double worstInside = 0.0, worstOutside = 0.0;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            const float* b = hdrPixel(back, x, y);
            const float* f = hdrPixel(front, x, y);
            const float* m = hdrPixel(mixed, x, y);
            if (relativeDifference(b, f) == 0.0) {  // the square does not cover this pixel
                worstOutside = std::max(worstOutside, relativeDifference(m, b));
                continue;
            }
            ++covered;
            float expected[3];
            for (int c = 0; c < 3; ++c)
                expected[c] = alpha * f[c] + (1.0f - alpha) * b[c];
            worstInside = std::max(worstInside, relativeDifference(m, expected));
        }
    }
    std::printf("covered %zu pixels, worst relative difference inside %.3g, outside %.3g\n",
                covered, worstInside, worstOutside);
    EXPECT_GT(covered, 100u);
    EXPECT_EQ(worstOutside, 0.0);
    // The opaque reference goes through the G-buffer (8-bit colour, 16-bit octahedral normal,
    // 16-bit roughness); the forward pass shades from full-precision inputs.
    EXPECT_LE(worstInside, 2e-3);
    EXPECT_EQ(mixed.nonFiniteHdrValues(), 0u);
    EXPECT_EQ(context.validationMessages(), 0u);
}

// Two overlapping unlit squares: whatever order the draws come in, the nearer one is
// composited over the farther one, exactly as the "over" operator says.
TEST(ForwardTransparency, SortsDrawsBackToFront) {
    GpuContext context(requiredValidation());
    StackScene scene;
    const std::array<float, 3> farRadiance{10.0f, 0.0f, 2.0f}, nearRadiance{0.0f, 4.0f, 8.0f};
    const float farAlpha = 0.5f, nearAlpha = 0.25f;
    scene.addPlane(1.0f, 1.0f, unlitEmissive(farRadiance, farAlpha));
    scene.addPlane(1.0f, 2.0f, unlitEmissive(nearRadiance, nearAlpha));
    CapturedFrame inOrder = scene.render(context, {0, 1});
    CapturedFrame reversed = scene.render(context, {1, 0});
    const float* centre = hdrPixel(inOrder, kSize / 2, kSize / 2);
    for (int c = 0; c < 3; ++c) {
        float farOverBlack = farAlpha * farRadiance[c];
        float expected = nearAlpha * nearRadiance[c] + (1.0f - nearAlpha) * farOverBlack;
        EXPECT_NEAR(centre[c], expected, 1e-5f * std::max(1.0f, expected)) << "channel " << c;
    }
    EXPECT_EQ(inOrder.hdrRgb, reversed.hdrRgb);
    EXPECT_EQ(context.validationMessages(), 0u);
}

// A blended square with 64 small local lights over it, optionally with an opaque floor far
// below: either way its clusters hold no opaque pixels, yet clustered culling must give it the
// lights brute force gives it.
static void expectClusteredMatchesBruteForceOnBlendedSquare(bool withOpaqueFloor) {
    GpuContext context(requiredValidation());
    StackScene scene;
    std::vector<uint32_t> order;
    if (withOpaqueFloor) {
        order.push_back(
            scene.addPlane(200.0f, -60.0f, lit({1.0f, 1.0f, 1.0f, 1.0f}, AlphaMode::Opaque)));
    }
    order.push_back(scene.addPlane(1.5f, 1.0f, lit({0.2f, 0.6f, 1.0f, 0.5f}, AlphaMode::Blend)));
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> xz(-2.0f, 2.0f), height(1.05f, 2.5f), radius(0.3f, 1.5f);
    for (int i = 0; i < 64; ++i) {
        scene.lights.push_back(pointLight({xz(rng), height(rng), xz(rng)}, 300.0f, radius(rng)));
    }
    RendererOptions bruteForce;
    bruteForce.lightCulling = LightCulling::BruteForce;
    CapturedFrame clustered = scene.render(context, order);
    CapturedFrame reference = scene.render(context, order, bruteForce);
    const float* centre = hdrPixel(clustered, kSize / 2, kSize / 2);
    EXPECT_GT(centre[0] + centre[1] + centre[2], 0.1f);  // lit, and only by local lights
    double worst = 0.0;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            worst = std::max(
                worst, relativeDifference(hdrPixel(clustered, x, y), hdrPixel(reference, x, y)));
        }
    }
    std::printf("clustered vs brute force: worst relative difference %.3g\n", worst);
    EXPECT_LE(worst, 1e-4);
    // Lists assigned in compute shaders are the CPU's lists: the same image, bit for bit.
    RendererOptions device;
    device.lightAssignment = LightAssignmentDevice::Gpu;
    CapturedFrame deviceAssigned = scene.render(context, order, device);
    EXPECT_EQ(deviceAssigned.hdrRgb, clustered.hdrRgb);
    EXPECT_EQ(context.validationMessages(), 0u);
}

TEST(ForwardTransparency, ClusteredLightsMatchBruteForceAwayFromOpaqueSurfaces) {
    expectClusteredMatchesBruteForceOnBlendedSquare(true);
}

// No opaque surface at all: the measured depth range is empty and the slicing degenerate
// (every blended fragment lands in the last slice), which must still be correct.
TEST(ForwardTransparency, ClusteredLightsMatchBruteForceWithOnlyBlendedSurfaces) {
    expectClusteredMatchesBruteForceOnBlendedSquare(false);
}

// A blended square 8 cm in front of an opaque floor, both in the same clusters, under small
// lights that reach the square but not the floor: the quarter masks of the light lists must
// come from the blended fragments too (the floor's pixel boxes alone would clear every bit),
// so the forward pass's masked lookup finds the lights brute force gives it.
TEST(ForwardTransparency, QuarterMasksHoldForBlendedSurfacesInFrontOfOpaqueOnes) {
    GpuContext context(requiredValidation());
    StackScene scene;
    std::vector<uint32_t> order;
    order.push_back(
        scene.addPlane(200.0f, 0.92f, lit({1.0f, 1.0f, 1.0f, 1.0f}, AlphaMode::Opaque)));
    order.push_back(scene.addPlane(1.5f, 1.0f, lit({0.2f, 0.6f, 1.0f, 0.5f}, AlphaMode::Blend)));
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> xz(-1.5f, 1.5f), height(1.2f, 1.6f);
    for (int i = 0; i < 96; ++i) {
        const float y = height(rng);
        // Radius between the distances to the square (y - 1) and to the floor (y - 0.92).
        scene.lights.push_back(pointLight({xz(rng), y, xz(rng)}, 300.0f, y - 0.93f));
    }
    RendererOptions bruteForce;
    bruteForce.lightCulling = LightCulling::BruteForce;
    CapturedFrame reference = scene.render(context, order, bruteForce);
    uint32_t litPixels = 0;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            const float* p = hdrPixel(reference, x, y);
            litPixels += p[0] + p[1] + p[2] > 0.0f ? 1u : 0u;  // the square, where lights reach
        }
    }
    EXPECT_GT(litPixels, 100u);
    for (LightAssignmentDevice device : {LightAssignmentDevice::Cpu, LightAssignmentDevice::Gpu}) {
        RendererOptions options;
        options.lightAssignment = device;
        CapturedFrame clustered = scene.render(context, order, options);
        double worst = 0.0;
        for (uint32_t y = 0; y < kSize; ++y) {
            for (uint32_t x = 0; x < kSize; ++x) {
                worst = std::max(worst, relativeDifference(hdrPixel(clustered, x, y),
                                                           hdrPixel(reference, x, y)));
            }
        }
        std::printf("%s lists vs brute force: worst relative difference %.3g, %u lit pixels\n",
                    device == LightAssignmentDevice::Gpu ? "GPU" : "CPU", worst, litPixels);
        EXPECT_LE(worst, 1e-4);
    }
    EXPECT_EQ(context.validationMessages(), 0u);
}

// Only frames with blended draws record the pass (and say so in --stats features).
TEST(ForwardTransparency, RecordedOnlyForFramesWithBlendedDraws) {
    GpuContext context(requiredValidation());
    StackScene scene;
    scene.addPlane(1.0f, 0.0f, lit({1.0f, 1.0f, 1.0f, 0.5f}, AlphaMode::Mask));
    scene.addPlane(1.0f, 1.0f, lit({1.0f, 1.0f, 1.0f, 0.5f}, AlphaMode::Blend));
    scene.lights.push_back(pointLight({0.0f, 3.0f, 0.0f}, 1000.0f, 10.0f));
    std::vector<std::string> withoutBlend, withBlend;
    scene.render(context, {0}, {}, &withoutBlend);
    scene.render(context, {0, 1}, {}, &withBlend);
    EXPECT_FALSE(hasFeature(withoutBlend, "forward_transparency"));
    EXPECT_TRUE(hasFeature(withBlend, "forward_transparency"));
    EXPECT_EQ(context.validationMessages(), 0u);
}
