// Volumetric lighting (issue 17, render/README.md "Volumetric lighting") against closed forms
// and a CPU integral of the single-scattering equation, at 128x128:
// - a uniform medium without lights attenuates an emissive wall by exp(-sigma_t d);
// - a point light in uniform fog in front of a black wall: the radiance each pixel sees is the
//   integral along its ray of sigma_s p(theta) E T_light T_view, E with eq. 9's falloff;
// - `off` renders exactly the frame without a medium;
// - a medium bounded to a box changes nothing outside it;
// - a static camera's frames stay put (the per-light volumes' dither and blur do not crawl);
// - hair, like blended surfaces, is seen through the medium in front of it, and a blended pane
//   and a wire get the sun's in-scattering where froxels march the sun per pixel;
// - the per-light volumes' rasterised proxies add what the tile lists add, and light the medium
//   around a camera inside a light's sphere.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>
#include <string>
#include <utility>

#include "candela/content/hair.h"
#include "candela/content/render_setting_table.h"
#include "candela/render/gpu_context.h"
#include "test_scene.h"

namespace candela::render::test {
namespace {

constexpr float kWallDistance = 6.0f;  // the wall is the plane z = -6, facing the camera

content::Material black() {
    content::Material m = lambertWhite();
    m.baseColorFactor = {0.0f, 0.0f, 0.0f, 1.0f};
    return m;
}

content::Material emissive(float luminance) {
    content::Material m = black();
    m.emissiveFactor = {1.0f, 1.0f, 1.0f};
    m.emissiveStrength = luminance;
    return m;
}

// A camera at the origin looking down -Z at a 20 m square wall kWallDistance away.
TestScene wallScene(const content::Material& wall) {
    TestScene scene;
    const glm::mat4 world =
        glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -kWallDistance)) *
        glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1.0f, 0.0f, 0.0f));
    scene.add(content::makePlane(10.0f, 1), wall, world);
    scene.lookAt(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    return scene;
}

CapturedFrame renderWithFog(GpuContext& context, TestScene& scene,
                            const std::optional<content::Fog>& fog, VolumetricsMode mode) {
    SceneResources resources(context);
    FrameInputs inputs = scene.prepare(resources);
    inputs.scene.fog = fog;
    RendererOptions options;
    options.volumetrics = mode;
    CapturedFrame frame =
        renderOffscreen(context, inputs, scene.width, scene.height, 1, &resources, options);
    EXPECT_EQ(frame.nonFiniteHdrValues(), 0u);
    return frame;
}

// The unit direction of pixel (x, y)'s view ray, the shaders' way (through the near plane).
glm::vec3 pixelRay(const TestScene& scene, uint32_t x, uint32_t y) {
    const glm::mat4 inverse = glm::inverse(scene.camera.projection * scene.camera.view);
    const glm::vec2 ndc((float(x) + 0.5f) / float(scene.width) * 2.0f - 1.0f,
                        (float(y) + 0.5f) / float(scene.height) * 2.0f - 1.0f);
    const glm::vec4 near = inverse * glm::vec4(ndc, 1.0f, 1.0f);
    return glm::normalize(glm::vec3(near) / near.w - scene.camera.position);
}

float henyeyGreenstein(float cosTheta, float g) {
    const float denominator = 1.0f + g * g - 2.0f * g * cosTheta;
    return (1.0f - g * g) /
           (4.0f * std::numbers::pi_v<float> * denominator * std::sqrt(denominator));
}

// The single-scattering integral along one ray from the camera to the wall, by the midpoint
// rule in fine steps: sigma_s p(theta) E(t) exp(-sigma_t |P - light|) exp(-sigma_t t) dt.
double scatteredAlongRay(const glm::vec3& direction, const LightInstance& light,
                         const content::Fog& fog) {
    const double sigmaT = double(fog.scattering) + fog.absorption;
    const double intensity = light.light.lumens / (4.0 * std::numbers::pi);
    const double invRadius = 1.0 / light.light.attenuationRadius;
    const double distance = kWallDistance / -direction.z;
    const int steps = 1500;
    const double dt = distance / steps;
    double sum = 0.0;
    for (int i = 0; i < steps; ++i) {
        const double t = (i + 0.5) * dt;
        const glm::dvec3 p = glm::dvec3(direction) * t;
        const glm::dvec3 d = p - glm::dvec3(light.position);
        const double d2 = glm::dot(d, d);
        const double ratio2 = d2 * invRadius * invRadius;
        const double window = std::pow(std::max(0.0, 1.0 - ratio2 * ratio2), 2.0);
        const double irradiance =
            intensity * window / (d2 + 1e-4) * std::exp(-sigmaT * std::sqrt(d2));
        const double cosTheta = glm::dot(d / std::sqrt(d2), -glm::dvec3(direction));
        sum += fog.scattering * henyeyGreenstein(float(cosTheta), fog.anisotropy) * irradiance *
               std::exp(-sigmaT * t) * dt;
    }
    return sum;
}

// Mean absolute error relative to the mean of `expected` over the pixels whose rays pass
// farther than `clearance` from the light (the singular peak right at it is left out).
double relativeMeanError(const CapturedFrame& frame, const TestScene& scene,
                         const LightInstance& light, const content::Fog& fog, float clearance) {
    double error = 0.0, total = 0.0;
    // Every second pixel each way: the CPU integral is the test's main cost.
    for (uint32_t y = 0; y < scene.height; y += 2) {
        for (uint32_t x = 0; x < scene.width; x += 2) {
            const glm::vec3 ray = pixelRay(scene, x, y);
            const glm::vec3 toLight = light.position - scene.camera.position;
            if (glm::length(toLight - ray * glm::dot(toLight, ray)) < clearance) continue;
            const double expected = scatteredAlongRay(ray, light, fog);
            error += std::abs(double(hdrPixel(frame, x, y)[1]) - expected);
            total += expected;
        }
    }
    return error / total;
}

class Volumetrics : public ::testing::Test {
protected:
    GpuContext context{requiredValidation()};
};

TEST_F(Volumetrics, UniformMediumWithoutLightsAttenuatesTheWallByItsTransmittance) {
    TestScene scene = wallScene(emissive(100.0f));
    content::Fog fog;
    fog.scattering = 0.08f;
    fog.absorption = 0.04f;
    for (VolumetricsMode mode : {VolumetricsMode::Reference, VolumetricsMode::Froxels}) {
        SCOPED_TRACE(candela::content::renderSettingName(mode).c_str());
        const CapturedFrame frame = renderWithFog(context, scene, fog, mode);
        double worst = 0.0;
        for (uint32_t y = 0; y < scene.height; y += 3) {
            for (uint32_t x = 0; x < scene.width; x += 3) {
                const glm::vec3 ray = pixelRay(scene, x, y);
                const double distance = kWallDistance / -ray.z;
                const double expected = 100.0 * std::exp(-0.12 * distance);
                worst = std::max(worst, std::abs(hdrPixel(frame, x, y)[0] - expected) / expected);
            }
        }
        // The reference integrates exactly; froxels interpolate the transmittance linearly
        // between exponential slice boundaries.
        EXPECT_LT(worst, mode == VolumetricsMode::Reference ? 1e-3 : 1e-2);
    }
}

TEST_F(Volumetrics, PointLightInFogMatchesTheSingleScatteringIntegral) {
    TestScene scene = wallScene(black());
    const LightInstance light = pointLight(glm::vec3(0.4f, 0.3f, -3.0f), 2000.0f, 8.0f);
    scene.lights.push_back(light);
    SceneResources resources(context);
    FrameInputs inputs = scene.prepare(resources);
    // One renderer per mode for the three phase functions: pipeline creation is most of a
    // frame's cost on lavapipe.
    for (VolumetricsMode mode :
         {VolumetricsMode::Reference, VolumetricsMode::Volumes, VolumetricsMode::Froxels}) {
        RendererOptions options;
        options.volumetrics = mode;
        FrameSequence frames(context, scene.width, scene.height, options);
        for (float g : {0.0f, 0.6f, -0.6f}) {
            content::Fog fog;
            fog.scattering = 0.05f;
            fog.absorption = 0.01f;
            fog.anisotropy = g;
            inputs.scene.fog = fog;
            const CapturedFrame frame = frames.render(inputs, resources);
            ASSERT_EQ(frame.nonFiniteHdrValues(), 0u);
            const double error = relativeMeanError(frame, scene, light, fog, 0.25f);
            std::printf("%s, g %+.1f: %.3f%% mean absolute error\n",
                        candela::content::renderSettingName(mode).c_str(), g, 100.0 * error);
            // The bounds: the reference within 2%, volumes and froxels within 10%.
            EXPECT_LT(error, mode == VolumetricsMode::Reference ? 0.02 : 0.10)
                << candela::content::renderSettingName(mode).c_str() << ", g " << g;
        }
    }
}

TEST_F(Volumetrics, OffRendersExactlyTheFrameWithoutAMedium) {
    TestScene scene = wallScene(lambertWhite());
    scene.lights.push_back(pointLight(glm::vec3(0.0f, 0.0f, -3.0f), 2000.0f, 8.0f));
    content::Fog fog;
    fog.scattering = 0.2f;
    const CapturedFrame clear =
        renderWithFog(context, scene, std::nullopt, VolumetricsMode::Froxels);
    const CapturedFrame off = renderWithFog(context, scene, fog, VolumetricsMode::Off);
    const CapturedFrame foggy = renderWithFog(context, scene, fog, VolumetricsMode::Froxels);
    ASSERT_EQ(clear.hdrRgb.size(), off.hdrRgb.size());
    EXPECT_EQ(std::memcmp(clear.hdrRgb.data(), off.hdrRgb.data(), clear.hdrRgb.size() * 4), 0);
    EXPECT_EQ(clear.ldrRgba, off.ldrRgba);
    EXPECT_NE(clear.ldrRgba, foggy.ldrRgba) << "the medium must show when it is on";
}

// A unit plane facing the camera 3 m in front of it, and a material drawn blended (full
// coverage): the transparency cases' pane.
const glm::mat4 kPaneAt3m =
    glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -3.0f)) *
    glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1.0f, 0.0f, 0.0f));

content::Material drawnBlended(content::Material material) {
    material.alphaMode = content::AlphaMode::Blend;
    return material;
}

// The transparency case: a blended pane of full coverage 3 m away in fog (in front of a wall
// 6 m away) shows what an opaque wall there shows: both attenuated by the medium in front of
// them, with its in-scattering added.
TEST_F(Volumetrics, ABlendedPaneInFogLooksLikeAnOpaqueWallAtItsDepth) {
    const glm::mat4 paneAt3m = kPaneAt3m;
    const content::Material glowing = emissive(50.0f);
    const content::Material pane = drawnBlended(glowing);
    TestScene opaque = wallScene(black());
    opaque.add(content::makePlane(1.0f, 1), glowing, paneAt3m);
    TestScene blended = wallScene(black());
    blended.add(content::makePlane(1.0f, 1), pane, paneAt3m);
    for (TestScene* scene : {&opaque, &blended}) {
        scene->lights.push_back(pointLight(glm::vec3(0.5f, 0.5f, -1.5f), 2000.0f, 8.0f));
    }
    content::Fog fog;
    fog.scattering = 0.1f;
    fog.absorption = 0.05f;
    const CapturedFrame a = renderWithFog(context, opaque, fog, VolumetricsMode::Froxels);
    const CapturedFrame b = renderWithFog(context, blended, fog, VolumetricsMode::Froxels);
    // The pane covers about the middle third; compare its inner pixels.
    double worst = 0.0, plain = 0.0;
    for (uint32_t y = 54; y < 74; ++y) {
        for (uint32_t x = 54; x < 74; ++x) {
            const float* p = hdrPixel(a, x, y);
            const float* q = hdrPixel(b, x, y);
            worst = std::max(worst, double(std::abs(p[1] - q[1]) / p[1]));
            plain = std::max(plain, double(std::abs(p[1] - 50.0f) / 50.0f));
        }
    }
    EXPECT_LT(worst, 2e-3);
    EXPECT_GT(plain, 0.2) << "the medium must change the pane";
}

// The same with the sun (froxels, which march it per pixel over their grid for the opaque
// frame): a shadowless sun scattering in the fog gives a blended pane, and a wire wide enough to
// cover the pane's inner pixels, from the grid's own sun channel the in-scattering the march
// gives the opaque wall; the wall behind the pane (opaque in every frame) keeps the march's,
// not twice it. 64x64, one renderer for the three frames.
TEST_F(Volumetrics, ABlendedPaneAndAWireInSunlitFogLookLikeAnOpaqueWallAtTheirDepth) {
    const glm::mat4 paneAt3m = kPaneAt3m;
    const content::Material glowing = emissive(50.0f);
    const content::Material pane = drawnBlended(glowing);
    content::Material wireMaterial;
    wireMaterial.shadingModel = content::ShadingModel::Unlit;
    wireMaterial.emissiveFactor = {1.0f, 1.0f, 1.0f};
    wireMaterial.emissiveStrength = 50.0f;
    content::Wire wire;  // 0.8 m thick across the view at 3 m: 15 pixels
    wire.positions = {{-10.0f, 0.0f, -3.0f}, {10.0f, 0.0f, -3.0f}};
    wire.segments = {0, 1};
    wire.radius = 0.4f;
    LightInstance sun;
    sun.light.type = content::LightType::Directional;
    sun.light.lux = 1000.0f;
    sun.light.castShadows = false;
    sun.direction = glm::normalize(glm::vec3(0.4f, -1.0f, -0.3f));
    content::Fog fog;
    fog.scattering = 0.1f;
    fog.absorption = 0.05f;
    fog.anisotropy = 0.3f;
    RendererOptions options;
    options.volumetrics = VolumetricsMode::Froxels;
    FrameSequence frames(context, 64, 64, options);
    auto render = [&](const content::Material* material, bool withWire) {
        TestScene scene = wallScene(black());
        scene.width = scene.height = 64;
        if (material) scene.add(content::makePlane(1.0f, 1), *material, paneAt3m);
        scene.lights.push_back(sun);
        SceneResources resources(context);
        FrameInputs inputs = scene.prepare(resources);
        inputs.scene.fog = fog;
        const std::vector<WireDraw> wires{{&wire, &wireMaterial, glm::mat4(1.0f)}};
        if (withWire) inputs.scene.wires = wires;
        CapturedFrame frame = frames.render(inputs, resources);
        EXPECT_EQ(frame.nonFiniteHdrValues(), 0u);
        return frame;
    };
    const CapturedFrame a = render(&glowing, false);
    const CapturedFrame b = render(&pane, false);
    const CapturedFrame w = render(nullptr, true);
    // The pane covers the middle 18 pixels each way and the wire the middle 15 rows; their
    // inner pixels, and the wall's well outside the pane.
    double worst = 0.0, worstWire = 0.0, plain = 0.0, wall = 0.0, sunlit = 0.0;
    for (uint32_t y = 0; y < 64; ++y) {
        for (uint32_t x = 0; x < 64; ++x) {
            const float* p = hdrPixel(a, x, y);
            const float* q = hdrPixel(b, x, y);
            const bool inside = x >= 26 && x < 38 && y >= 26 && y < 38;
            const bool outside = x < 12 || x >= 52 || y < 12 || y >= 52;
            for (int c = 0; c < 3; ++c) {
                if (inside) {
                    worst = std::max(worst, double(std::abs(p[c] - q[c]) / p[c]));
                    plain = std::max(plain, double(std::abs(p[c] - 50.0f) / 50.0f));
                    if (y >= 29 && y < 35) {
                        const float seen = hdrPixel(w, x, y)[c];
                        worstWire = std::max(worstWire, double(std::abs(p[c] - seen) / p[c]));
                    }
                } else if (outside) {
                    wall = std::max(wall, double(std::abs(p[c] - q[c]) / p[c]));
                    sunlit = std::max(sunlit, double(p[c]));
                }
            }
        }
    }
    std::printf(
        "in sunlit fog against an opaque wall: blended pane worst %.5f, wire %.5f (the fog "
        "changes the wall by %.3f); the wall around, worst %.2e (its fog up to %.3g)\n",
        worst, worstWire, plain, wall, sunlit);
    EXPECT_GT(plain, 0.1) << "the medium must change the pane";
    EXPECT_GT(sunlit, 1.0) << "the sun must scatter in front of the wall";
    EXPECT_LT(worst, 1e-2);
    EXPECT_LT(worstWire, 1e-2);
    // The wall's fog, marched per pixel in every frame, differs only where the march's cascades
    // (fitted to the depths, which the opaque pane changes) place its samples otherwise: 1.8 %.
    // A sun counted in the grid too would double it.
    EXPECT_LT(wall, 0.05) << "the opaque frame must keep the march's sun, once";
}

// Shadows carve the medium: a box beside a shadow-casting point light darkens the fog in the
// wedge behind it (from the light), and leaves the fog above that wedge as it was.
TEST_F(Volumetrics, ShadowsCarveTheMediumBehindABox) {
    TestScene scene = wallScene(black());
    scene.add(content::makeBox({0.15f, 0.15f, 0.15f}), black(),
              glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -4.0f)));
    scene.lights.push_back(pointLight(glm::vec3(-0.8f, 0.0f, -4.0f), 2000.0f, 8.0f));
    SceneResources resources(context);
    FrameInputs inputs = scene.prepare(resources);
    content::Fog fog;
    fog.scattering = 0.1f;
    inputs.scene.fog = fog;
    // Mean green over a block of pixels: the wedge right of the box at its height, and the
    // same columns 40 pixels higher, where the rays pass above the wedge.
    auto block = [](const CapturedFrame& f, uint32_t y0) {
        double sum = 0.0;
        for (uint32_t y = y0; y < y0 + 8; ++y)
            for (uint32_t x = 80; x < 100; ++x)
                sum += hdrPixel(f, x, y)[1];
        return sum / 160.0;
    };
    for (VolumetricsMode mode :
         {VolumetricsMode::Reference, VolumetricsMode::Volumes, VolumetricsMode::Froxels}) {
        SCOPED_TRACE(candela::content::renderSettingName(mode).c_str());
        RendererOptions options;
        options.volumetrics = mode;
        FrameSequence frames(context, scene.width, scene.height, options);
        scene.lights[0].light.castShadows = false;
        const CapturedFrame lit = frames.render(inputs, resources);
        scene.lights[0].light.castShadows = true;
        const CapturedFrame shadowed = frames.render(inputs, resources);
        const double wedge = block(shadowed, 60) / block(lit, 60);
        const double above = block(shadowed, 20) / block(lit, 20);
        std::printf("%s: fog behind the box %.3f of unshadowed, above it %.3f\n",
                    candela::content::renderSettingName(mode).c_str(), wedge, above);
        EXPECT_LT(wedge, 0.85);
        EXPECT_NEAR(above, 1.0, 0.03);
    }
}

// A 1 x 0.6 m rect light 3 m ahead, edge-on to the camera and facing +X (issue 15's one-sided
// Lambertian emitter): at each point of the medium in front of it, E is the irradiance of a
// surface facing its centre (the sum over 32 x 20 patches of L cos_e cos_r / d^2 dA, cos_r
// clamped at the horizon as the exact form factor clips it), and nothing behind it. Scattered
// as a point (the old way: its luminance as a point intensity at the centre) it misses the
// integral and lights the medium behind too.
// 64x64, every second pixel of the right half.
TEST_F(Volumetrics, ARectLightScattersAsAnAreaLight) {
    TestScene scene = wallScene(black());
    scene.width = scene.height = 64;
    LightInstance rect;
    rect.light.type = content::LightType::Rect;
    rect.light.lumens = 2000.0f;
    rect.light.attenuationRadius = 8.0f;
    rect.light.width = 1.0f;   // along tubeAxis, world Z
    rect.light.height = 0.6f;  // world Y
    rect.position = {0.0f, 0.0f, -3.0f};
    rect.direction = {1.0f, 0.0f, 0.0f};
    rect.tubeAxis = {0.0f, 0.0f, 1.0f};
    scene.lights.push_back(rect);
    content::Fog fog;
    fog.scattering = 0.05f;
    fog.absorption = 0.01f;
    fog.anisotropy = 0.3f;
    const double sigmaT = double(fog.scattering) + fog.absorption;
    const double luminance = rect.light.lumens / (std::numbers::pi * 1.0 * 0.6);
    const glm::dvec3 centre(rect.position), normal(rect.direction);
    auto irradiance = [&](const glm::dvec3& p) {
        const glm::dvec3 toCentre = centre - p;
        const double d2c = glm::dot(toCentre, toCentre);
        const double ratio2 = d2c / (8.0 * 8.0);
        const double window = std::pow(std::max(0.0, 1.0 - ratio2 * ratio2), 2.0);
        if (window <= 0.0 || glm::dot(p - centre, normal) <= 0.0) return 0.0;
        const glm::dvec3 facing = toCentre / std::sqrt(d2c);
        const int nz = 32, ny = 20;
        const double dA = (1.0 / nz) * (0.6 / ny);
        double e = 0.0;
        for (int j = 0; j < ny; ++j) {
            for (int i = 0; i < nz; ++i) {
                const glm::dvec3 q =
                    centre + glm::dvec3(0.0, -0.3 + (j + 0.5) * 0.6 / ny, -0.5 + (i + 0.5) / nz);
                const glm::dvec3 d = p - q;
                const double d2 = glm::dot(d, d);
                const double cosEmit = glm::dot(normal, d) / std::sqrt(d2);
                const double cosReceive = std::max(0.0, -glm::dot(facing, d) / std::sqrt(d2));
                e += cosEmit * cosReceive / d2 * dA;
            }
        }
        return luminance * window * e;
    };
    SceneResources resources(context);
    FrameInputs inputs = scene.prepare(resources);
    inputs.scene.fog = fog;
    for (VolumetricsMode mode : {VolumetricsMode::Reference, VolumetricsMode::Volumes}) {
        SCOPED_TRACE(candela::content::renderSettingName(mode).c_str());
        RendererOptions options;
        options.volumetrics = mode;
        const CapturedFrame frame =
            renderOffscreen(context, inputs, scene.width, scene.height, 1, &resources, options);
        ASSERT_EQ(frame.nonFiniteHdrValues(), 0u);
        double error = 0.0, total = 0.0, behind = 0.0;
        uint32_t counted = 0;
        for (uint32_t y = 0; y < scene.height; y += 2) {
            for (uint32_t x = 0; x < scene.width; x += 2) {
                const glm::dvec3 ray(pixelRay(scene, x, y));
                const double seen = hdrPixel(frame, x, y)[1];
                if (ray.x < 0.0) {
                    // Behind the emitter (left of its plane x = 0, away from the blur's
                    // reach across the middle).
                    if (x + 8 < scene.width / 2) behind = std::max(behind, seen);
                    continue;
                }
                const int steps = 200;
                const double dt = kWallDistance / -ray.z / steps;
                double expected = 0.0;
                for (int i = 0; i < steps; ++i) {
                    const double t = (i + 0.5) * dt;
                    const glm::dvec3 p = ray * t;
                    const double cosTheta = glm::dot(glm::normalize(p - centre), -ray);
                    expected += fog.scattering * henyeyGreenstein(float(cosTheta), fog.anisotropy) *
                                irradiance(p) * std::exp(-sigmaT * (glm::length(p - centre) + t)) *
                                dt;
                }
                error += std::abs(seen - expected);
                total += expected;
                ++counted;
            }
        }
        std::printf("%s: rect light %.3f%% mean absolute error, behind it at most %g\n",
                    candela::content::renderSettingName(mode).c_str(), 100.0 * error / total,
                    behind);
        EXPECT_LT(error / total, mode == VolumetricsMode::Reference ? 0.02 : 0.10);
        EXPECT_LT(behind, 1e-3 * total / counted) << "the medium behind the emitter is unlit";
    }
}

// The sun's volume is the whole screen, marched cascade by cascade through its shadow maps: a
// black slab over the left half (x < 0) of the space in front of the camera keeps the sun,
// straight down, off the medium below it, so the lower-left pixels' fog is dark while their
// mirror images on the right keep theirs; without shadows the two sides match. The per-light
// volumes only: the reference looks each sample's cascade up (mediumShadow), as before.
TEST_F(Volumetrics, TheSunsCascadesCarveItsShaftsInTheMedium) {
    TestScene scene = wallScene(black());
    scene.width = scene.height = 64;
    scene.add(content::makeBox({5.0f, 0.05f, 5.0f}), black(),
              glm::translate(glm::mat4(1.0f), glm::vec3(-5.0f, 0.8f, -4.0f)));
    LightInstance sun;
    sun.light.type = content::LightType::Directional;
    sun.light.lux = 10000.0f;
    sun.direction = {0.0f, -1.0f, 0.0f};
    scene.lights.push_back(sun);
    SceneResources resources(context);
    FrameInputs inputs = scene.prepare(resources);
    content::Fog fog;
    fog.scattering = 0.05f;
    inputs.scene.fog = fog;
    // Mean green of the lower-left block and of its mirror image on the right.
    auto sides = [&](const CapturedFrame& f) {
        double left = 0.0, right = 0.0;
        for (uint32_t y = 40; y < 56; ++y) {
            for (uint32_t x = 4; x < 24; ++x) {
                left += hdrPixel(f, x, y)[1];
                right += hdrPixel(f, scene.width - 1 - x, y)[1];
            }
        }
        return left / right;
    };
    // Froxels march the sun per pixel as the volumes do and leave it out of their grid: over the
    // black wall the two modes give the same fog, where a sun counted in both the grid and the
    // march would give twice as much.
    double rightSide[2] = {0.0, 0.0};
    for (const VolumetricsMode mode : {VolumetricsMode::Volumes, VolumetricsMode::Froxels}) {
        SCOPED_TRACE(candela::content::renderSettingName(mode).c_str());
        RendererOptions options;
        options.volumetrics = mode;
        FrameSequence frames(context, scene.width, scene.height, options);
        scene.lights[0].light.castShadows = false;
        const CapturedFrame unshadowed = frames.render(inputs, resources);
        const double lit = sides(unshadowed);
        scene.lights[0].light.castShadows = true;
        const double shadowed = sides(frames.render(inputs, resources));
        for (uint32_t y = 40; y < 56; ++y)
            for (uint32_t x = 40; x < 60; ++x)
                rightSide[mode == VolumetricsMode::Froxels] += hdrPixel(unshadowed, x, y)[1];
        std::printf("%s: sunlit fog left / right %.3f, with the slab's shadow %.3f\n",
                    candela::content::renderSettingName(mode).c_str(), lit, shadowed);
        EXPECT_NEAR(lit, 1.0, 0.03);
        EXPECT_LT(shadowed, 0.2);
    }
    std::printf("froxels / volumes, the sunlit fog: %.4f\n", rightSide[1] / rightSide[0]);
    EXPECT_GT(rightSide[0], 0.0);
    EXPECT_NEAR(rightSide[1] / rightSide[0], 1.0, 0.01);
}

// Hair in fog (issue 16: the hair resolve reads the medium in front of it, as blended surfaces
// and wires do): a curtain of horizontal strands 3 m away, dense enough to hide the wall
// behind it, shows what an opaque wall at its depth would: its own radiance H attenuated by the
// fog in front, with the fog's in-scattering added, H T + L. T and L at 3 m come from two opaque
// walls there in the same fog, an emissive one (50 T + L) and a black one (L).
TEST_F(Volumetrics, HairInFogLooksLikeAnOpaqueWallAtItsDepth) {
    const glm::mat4 wallAt3m =
        glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -3.0f)) *
        glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1.0f, 0.0f, 0.0f));
    content::Fog fog;
    fog.scattering = 0.1f;
    fog.absorption = 0.05f;
    const LightInstance light = pointLight(glm::vec3(0.5f, 0.5f, -1.5f), 2000.0f, 8.0f);
    // 0.03 m wide strands every 4 mm, 0.55 of a 54 mm pixel each: 13 per pixel let 3e-5 through.
    content::Hair curtain;
    for (uint32_t i = 0; i < 250; ++i) {
        const float y = -0.5f + 0.004f * float(i);
        curtain.positions.push_back({-0.5f, y, -3.0f});
        curtain.positions.push_back({0.5f, y, -3.0f});
        curtain.segments.push_back(2 * i);
        curtain.segments.push_back(2 * i + 1);
    }
    curtain.rootToTip = content::strandParameters(curtain.positions, curtain.segments);
    content::HairStyle style;
    style.rootRadius = style.tipRadius = 0.015f;
    style.color = {0.6f, 0.4f, 0.25f};
    const std::vector<HairDraw> hair{{&curtain, &style, glm::mat4(1.0f)}};
    auto render = [&](std::optional<content::Material> wall, bool withHair,
                      const std::optional<content::Fog>& medium) {
        TestScene scene = wallScene(black());
        scene.width = scene.height = 64;
        scene.lookAt(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
        if (wall) scene.add(content::makePlane(1.0f, 1), *wall, wallAt3m);
        scene.lights.push_back(light);
        SceneResources resources(context);
        FrameInputs inputs = scene.prepare(resources);
        inputs.scene.fog = medium;
        if (withHair) inputs.scene.hair = hair;
        RendererOptions options;
        options.volumetrics = VolumetricsMode::Froxels;
        CapturedFrame frame =
            renderOffscreen(context, inputs, scene.width, scene.height, 1, &resources, options);
        EXPECT_EQ(frame.nonFiniteHdrValues(), 0u);
        return frame;
    };
    const CapturedFrame clearHair = render(std::nullopt, true, std::nullopt);
    const CapturedFrame foggyHair = render(std::nullopt, true, fog);
    const CapturedFrame glowing = render(emissive(50.0f), false, fog);
    const CapturedFrame dark = render(black(), false, fog);
    // The curtain covers the middle 18 pixels each way; its inner pixels.
    double worst = 0.0, change = 1.0;
    for (uint32_t y = 26; y < 38; ++y) {
        for (uint32_t x = 26; x < 38; ++x) {
            double pixelChange = 0.0;  // in the channel the fog changes most (H T + L ~ H in one)
            for (int c = 0; c < 3; ++c) {
                const double h = hdrPixel(clearHair, x, y)[c];
                const double inScattered = hdrPixel(dark, x, y)[c];
                const double transmittance = (hdrPixel(glowing, x, y)[c] - inScattered) / 50.0;
                const double expected = h * transmittance + inScattered;
                const double seen = hdrPixel(foggyHair, x, y)[c];
                worst = std::max(worst, std::abs(seen - expected) / expected);
                pixelChange = std::max(pixelChange, std::abs(seen - h) / h);
            }
            change = std::min(change, pixelChange);
        }
    }
    std::printf(
        "hair in fog against an opaque wall at its depth: worst %.5f (the fog changes it "
        "by at least %.3f)\n",
        worst, change);
    EXPECT_GT(change, 0.1) << "the medium must change the hair";
    EXPECT_LT(worst, 5e-3);
}

// Stability: with the camera still (no TAA jitter), each of 8 frames differs from the one
// before by under 2% at every pixel, leaving out the rays that pass within 0.25 m of the light
// as the integral test does. The per-light volumes' Bayer offsets are fixed to the screen and
// the blur spans all 16 of them, so nothing crawls; froxels sample fixed froxel centres. A
// dither that moved from frame to frame (temporal dithering) fails it. With TAA's jittered
// rays the change near the light is larger (render/README.md "Volumetric lighting"). 64x64
// keeps it cheap.
TEST_F(Volumetrics, AStaticCameraSeesAStableMediumOverEightFrames) {
    TestScene scene = wallScene(black());
    scene.width = scene.height = 64;
    const LightInstance light = pointLight(glm::vec3(0.6f, 0.3f, -3.0f), 2000.0f, 8.0f);
    scene.lights.push_back(light);
    SceneResources resources(context);
    FrameInputs inputs = scene.prepare(resources);
    content::Fog fog;
    fog.scattering = 0.08f;
    fog.absorption = 0.02f;
    fog.anisotropy = 0.3f;
    inputs.scene.fog = fog;
    std::vector<bool> counted(size_t(scene.width) * scene.height);
    for (uint32_t y = 0; y < scene.height; ++y) {
        for (uint32_t x = 0; x < scene.width; ++x) {
            const glm::vec3 ray = pixelRay(scene, x, y);
            const glm::vec3 toLight = light.position - scene.camera.position;
            counted[size_t(y) * scene.width + x] =
                glm::length(toLight - ray * glm::dot(toLight, ray)) >= 0.25f;
        }
    }
    const std::pair<VolumetricsMode, AntiAliasing> cases[] = {
        {VolumetricsMode::Volumes, AntiAliasing::Off},
        {VolumetricsMode::Froxels, AntiAliasing::Off},
        {VolumetricsMode::Volumes, AntiAliasing::Taa},
        {VolumetricsMode::Froxels, AntiAliasing::Taa}};
    for (const auto& [mode, aa] : cases) {
        SCOPED_TRACE(std::string(candela::content::renderSettingName(mode).c_str()) + ", --aa " +
                     candela::content::renderSettingName(aa).c_str());
        RendererOptions options;
        options.volumetrics = mode;
        options.aa = aa;
        FrameSequence frames(context, scene.width, scene.height, options);
        CapturedFrame previous = frames.render(inputs, resources);
        double worst = 0.0;
        for (int frame = 1; frame < 8; ++frame) {
            const CapturedFrame next = frames.render(inputs, resources);
            for (size_t p = 0; p < counted.size(); ++p) {
                const float before = previous.hdrRgb[3 * p + 1];
                if (!counted[p] || !(before > 0.0f)) continue;
                worst = std::max(worst, double(std::abs(next.hdrRgb[3 * p + 1] - before) / before));
            }
            previous = next;
        }
        std::printf("%s, --aa %s: largest change from one frame to the next %.3f%%\n",
                    candela::content::renderSettingName(mode).c_str(),
                    candela::content::renderSettingName(aa).c_str(), 100.0 * worst);
        EXPECT_LT(worst, 0.02);
    }
}

// A Fog bounded to a box (content::FogBounds) is air outside it: in every mode, a pixel whose
// view ray misses the box sees exactly what it sees without a medium, though the light stands
// in the box and an unbounded medium would glow around it there; rays through the box are
// attenuated and lit. The box: x in [-10, -1] between 0.5 and 5.5 m in front of the camera.
TEST_F(Volumetrics, AMediumBoundedToABoxScattersAndAttenuatesNothingOutsideIt) {
    TestScene scene = wallScene(emissive(50.0f));
    scene.width = scene.height = 48;
    scene.lights.push_back(pointLight(glm::vec3(-2.0f, 0.0f, -3.0f), 2000.0f, 8.0f));
    content::Fog fog;
    fog.scattering = 0.1f;
    fog.absorption = 0.05f;
    fog.bounds = content::FogBounds{{-10.0f, -10.0f, -5.5f}, {-1.0f, 10.0f, -0.5f}};
    const CapturedFrame clear =
        renderWithFog(context, scene, std::nullopt, VolumetricsMode::Reference);
    for (VolumetricsMode mode :
         {VolumetricsMode::Reference, VolumetricsMode::Volumes, VolumetricsMode::Froxels}) {
        SCOPED_TRACE(candela::content::renderSettingName(mode).c_str());
        const CapturedFrame foggy = renderWithFog(context, scene, fog, mode);
        double outside = 0.0;  // the largest relative change where rays miss the box
        double inside = 1.0;   // the smallest where rays cross 3 m of it or more
        for (uint32_t y = 0; y < scene.height; ++y) {
            for (uint32_t x = 0; x < scene.width; ++x) {
                const glm::vec3 ray = pixelRay(scene, x, y);
                const float slope = ray.x / -ray.z;  // x per metre toward the wall
                const double before = hdrPixel(clear, x, y)[1];
                const double change = std::abs(hdrPixel(foggy, x, y)[1] - before) / before;
                // Rays right of the centre never reach x = -1; the froxels' 8x8-pixel columns
                // and the volumes' blur reach about 10 pixels, hence the margin.
                if (slope > 0.15f) outside = std::max(outside, change);
                if (slope < -1.0f / 2.5f) inside = std::min(inside, change);
            }
        }
        std::printf(
            "%s: bounded fog changes pixels outside its box by at most %.5f%%, those "
            "through it by at least %.1f%%\n",
            candela::content::renderSettingName(mode).c_str(), 100.0 * outside, 100.0 * inside);
        EXPECT_LT(outside, 1e-4);
        EXPECT_GT(inside, 0.05);
    }
}

// The per-light volumes' two ways to the same sums (render/README.md "Volumetric lighting"):
// each light's proxy mesh rasterised (VolumetricsSettings::volumeProxies) and the compute march
// over CPU light lists per tile march the same samples of the same segments, so the proxies must
// cover every pixel whose ray meets a volume: point and spot lights with the camera outside and
// inside them, a rect light around the camera and a disk light far off (their hemispheres, the
// half-space in front of the emitter), and lights off screen and wholly behind the wall
// (nothing to add).
TEST_F(Volumetrics, ProxyMeshesAddWhatTheTileListsAdd) {
    TestScene scene = wallScene(black());
    scene.width = scene.height = 64;
    scene.lights.push_back(pointLight(glm::vec3(1.5f, 0.5f, -4.0f), 2000.0f, 1.5f));
    scene.lights.push_back(pointLight(glm::vec3(0.3f, -0.2f, -0.5f), 300.0f, 3.0f));  // holds it
    LightInstance spot = pointLight(glm::vec3(-1.5f, 1.5f, -3.0f), 2000.0f, 4.0f);
    spot.light.type = content::LightType::Spot;
    spot.light.outerConeAngle = 0.5f;
    spot.direction = glm::normalize(glm::vec3(0.3f, -1.0f, -0.2f));
    scene.lights.push_back(spot);
    LightInstance around = spot;  // its cone holds the camera
    around.position = glm::vec3(0.0f, 0.0f, 2.0f);
    around.direction = glm::vec3(0.0f, 0.0f, -1.0f);
    around.light.outerConeAngle = 0.3f;
    around.light.attenuationRadius = 7.0f;
    around.light.lumens = 500.0f;
    scene.lights.push_back(around);
    LightInstance rect;
    rect.light.type = content::LightType::Rect;
    rect.light.lumens = 2000.0f;
    rect.light.attenuationRadius = 3.0f;
    rect.light.width = 1.0f;
    rect.light.height = 0.6f;
    rect.position = {0.5f, -1.0f, -3.0f};
    rect.direction = {0.0f, 1.0f, 0.0f};
    rect.tubeAxis = {1.0f, 0.0f, 0.0f};
    scene.lights.push_back(rect);
    LightInstance disk = rect;  // facing the camera from afar: its hemisphere's front faces
    disk.light.type = content::LightType::Disk;
    disk.light.attenuationRadius = 1.5f;
    disk.position = {-1.0f, 0.8f, -4.5f};
    disk.direction = glm::normalize(glm::vec3(0.3f, 0.0f, 1.0f));
    disk.tubeAxis = glm::normalize(glm::vec3(1.0f, 0.0f, -0.3f));
    scene.lights.push_back(disk);
    scene.lights.push_back(pointLight(glm::vec3(0.0f, 0.0f, -9.0f), 2000.0f, 2.5f));  // behind
    scene.lights.push_back(pointLight(glm::vec3(0.0f, 0.0f, 5.0f), 2000.0f, 2.0f));   // off
    content::Fog fog;
    fog.scattering = 0.05f;
    fog.absorption = 0.01f;
    fog.anisotropy = 0.3f;
    SceneResources resources(context);
    FrameInputs inputs = scene.prepare(resources);
    inputs.scene.fog = fog;
    auto render = [&](bool proxies, size_t lights) {
        RendererOptions options;
        options.volumetrics = VolumetricsMode::Volumes;
        options.volumeProxies = proxies;
        FrameInputs subset = inputs;
        subset.scene.lights = inputs.scene.lights.subspan(0, lights);
        CapturedFrame frame =
            renderOffscreen(context, subset, scene.width, scene.height, 1, &resources, options);
        EXPECT_EQ(frame.nonFiniteHdrValues(), 0u);
        return frame;
    };
    const CapturedFrame proxies = render(true, scene.lights.size());
    const CapturedFrame tiles = render(false, scene.lights.size());
    double largest = 0.0, worst = 0.0;
    for (size_t i = 0; i < tiles.hdrRgb.size(); ++i) {
        largest = std::max(largest, double(tiles.hdrRgb[i]));
        worst = std::max(worst, std::abs(double(proxies.hdrRgb[i]) - tiles.hdrRgb[i]));
    }
    std::printf("proxies against tile lists: largest difference %.2e of the brightest %.3g\n",
                worst / largest, largest);
    EXPECT_GT(largest, 0.0);
    // The same samples summed in another order: float rounding only.
    EXPECT_LT(worst, 1e-4 * largest);
    // The lights behind the wall and behind the camera add nothing, to the bit.
    const CapturedFrame without = render(true, scene.lights.size() - 2);
    ASSERT_EQ(without.hdrRgb.size(), proxies.hdrRgb.size());
    EXPECT_EQ(std::memcmp(without.hdrRgb.data(), proxies.hdrRgb.data(), proxies.hdrRgb.size() * 4),
              0);
}

// The camera inside a point light's range sphere: its proxy's back faces (untested against the
// depth, the front ones behind the near plane) still cover the screen, and the medium around the
// camera matches the single-scattering integral.
TEST_F(Volumetrics, TheCameraInsideALightsSphereStillGetsItsScattering) {
    TestScene scene = wallScene(black());
    scene.width = scene.height = 64;
    const LightInstance light = pointLight(glm::vec3(0.2f, 0.1f, -1.0f), 500.0f, 3.0f);
    scene.lights.push_back(light);
    content::Fog fog;
    fog.scattering = 0.05f;
    fog.absorption = 0.01f;
    SceneResources resources(context);
    FrameInputs inputs = scene.prepare(resources);
    inputs.scene.fog = fog;
    RendererOptions options;
    options.volumetrics = VolumetricsMode::Volumes;
    options.volumeProxies = true;
    const CapturedFrame frame =
        renderOffscreen(context, inputs, scene.width, scene.height, 1, &resources, options);
    ASSERT_EQ(frame.nonFiniteHdrValues(), 0u);
    const double error = relativeMeanError(frame, scene, light, fog, 0.25f);
    std::printf("camera inside the light's sphere: %.3f%% mean absolute error\n", 100.0 * error);
    EXPECT_LT(error, 0.10);
    // Every corner's ray crosses the sphere (the camera is 1 m from its centre): lit.
    for (uint32_t y : {0u, scene.height - 1})
        for (uint32_t x : {0u, scene.width - 1})
            EXPECT_GT(hdrPixel(frame, x, y)[1], 0.0f) << x << ", " << y;
}

}  // namespace
}  // namespace candela::render::test
