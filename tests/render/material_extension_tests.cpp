// Issue 21's material extensions on the real renderer: the clear coat's white furnace (no
// configuration reflects more than a uniform white sky gives it), the coat drawn at all, and
// the anisotropic lobe stretching a point light's highlight along the tangent.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <memory>

#include "candela/render/environment.h"
#include "ibl_test_support.h"
#include "test_scene.h"

using namespace candela::render;
using namespace candela::render::test;
using candela::content::makeSphere;
using candela::content::Material;

namespace {

float frameMax(const CapturedFrame& frame) {
    float m = 0.0f;
    for (float v : frame.hdrRgb)
        m = std::max(m, v);
    return m;
}

double centreMean(const CapturedFrame& frame) {
    double sum = 0.0;
    int n = 0;
    for (uint32_t y = frame.height / 2 - 8; y < frame.height / 2 + 8; ++y) {
        for (uint32_t x = frame.width / 2 - 8; x < frame.width / 2 + 8; ++x) {
            for (int c = 0; c < 3; ++c, ++n)
                sum += hdrPixel(frame, x, y)[c];
        }
    }
    return sum / n;
}

struct Base {
    const char* name;
    float metallic;
    float roughness;
    float specular;
    bool checkedByReference;
};

}  // namespace

// Every pixel of the frame (the sphere and the sky behind it, which is exactly 1), coated
// against the same base uncoated: a coat never adds light, and over bases that alone reflect
// at most the sky (white metals, a white Lambert base) nothing exceeds 1. The white dielectric
// (Specular 0.5) alone reflects up to 1.16 of the sky at grazing angles (Karis 2013's ("Real
// Shading in Unreal Engine 4") model adds the specular lobe to a diffuse base without taking it
// away), and coated it must stay under that. Coats (factor, roughness) (1, 0), (0.5, 0.3), (1, 1).
// Tolerance 1e-2: fp16 cubes and the 16-bit LUT round; the reference's Monte Carlo (256 + 256
// samples) gets 3e-2.
TEST(ClearCoatFurnace, NoConfigurationReflectsMoreThanTheSky) {
    GpuContext& context = sharedContext();
    std::shared_ptr<const Environment> sky = Environment::uniform(context, 1.0f);
    // The reference (slow on lavapipe) checks the half coat over the metal and the dielectric.
    const Base bases[] = {{"white metal", 1.0f, 0.2f, 0.5f, true},
                          {"rough white metal", 1.0f, 1.0f, 0.5f, false},
                          {"white Lambert", 0.0f, 1.0f, 0.0f, false},
                          {"white dielectric", 0.0f, 0.5f, 0.5f, true}};
    const std::pair<float, float> coats[] = {{1.0f, 0.0f}, {0.5f, 0.3f}, {1.0f, 1.0f}};
    for (IblMode mode : kIblModes) {
        const bool reference = mode == IblMode::Reference;
        RendererOptions options;
        options.ibl = mode;
        options.referenceSamples = 256;
        const float tolerance = reference ? 0.03f : 0.01f;
        for (const Base& base : bases) {
            if (reference && !base.checkedByReference) continue;
            Material m;
            m.baseColorFactor = {1.0f, 1.0f, 1.0f, 1.0f};
            m.metallicFactor = base.metallic;
            m.roughnessFactor = base.roughness;
            m.specular = base.specular;
            const CapturedFrame bare = sphereInSky(m, sky).render(context, options);
            for (const auto& [factor, coatRoughness] : coats) {
                if (reference && factor != 0.5f) continue;
                m.clearcoatFactor = factor;
                m.clearcoatRoughnessFactor = coatRoughness;
                CapturedFrame frame = sphereInSky(m, sky).render(context, options);
                float worstGain = -1e30f;  // coated - max(1, bare), over every pixel
                for (size_t i = 0; i < frame.hdrRgb.size(); ++i) {
                    worstGain =
                        std::max(worstGain, frame.hdrRgb[i] - std::max(1.0f, bare.hdrRgb[i]));
                }
                std::printf(
                    "%-10s %-18s coat %.1f roughness %.1f: max %.4f (bare %.4f), centre %.4f, "
                    "worst gain %+.4f\n",
                    iblModeName(mode), base.name, factor, coatRoughness, frameMax(frame),
                    frameMax(bare), centreMean(frame), worstGain);
                EXPECT_LE(worstGain, tolerance) << iblModeName(mode) << " " << base.name << " coat "
                                                << factor << " roughness " << coatRoughness;
                if (base.metallic == 1.0f || base.specular == 0.0f) {
                    EXPECT_LE(frameMax(frame), 1.0f + tolerance)
                        << iblModeName(mode) << " " << base.name;
                }
            }
        }
    }
    EXPECT_EQ(context.validationMessages(), 0u);
}

// A black base (no diffuse, F0 = 0) shows the coat alone: a smooth coat seen head-on reflects
// its F0 of 0.04 of the sky; without the coat the sphere is black.
TEST(ClearCoatFurnace, CoatAloneReflectsItsFresnel) {
    GpuContext& context = sharedContext();
    std::shared_ptr<const Environment> sky = Environment::uniform(context, 1.0f);
    Material m;
    m.baseColorFactor = {0.0f, 0.0f, 0.0f, 1.0f};
    m.metallicFactor = 0.0f;
    m.specular = 0.0f;
    m.roughnessFactor = 0.5f;
    RendererOptions options;
    options.ibl = IblMode::SplitSum;
    const double bare = centreMean(sphereInSky(m, sky).render(context, options));
    m.clearcoatFactor = 1.0f;
    m.clearcoatRoughnessFactor = 0.0f;
    const double coated = centreMean(sphereInSky(m, sky).render(context, options));
    std::printf("black base: bare %.5f, coated %.5f\n", bare, coated);
    EXPECT_LT(bare, 1e-3);
    EXPECT_NEAR(coated, 0.04, 0.01);
    EXPECT_EQ(context.validationMessages(), 0u);
}

// A point light's highlight on a metal sphere whose tangents run around it (horizontally in
// the image): isotropic, about as wide as tall; anisotropic (strength 0.9), stretched along the
// tangent, so clearly wider than tall; with anisotropyRotation a quarter turn, taller than
// wide. Extents of the pixels above a tenth of the peak.
TEST(AnisotropicLobe, StretchesTheHighlightAlongTheTangent) {
    GpuContext& context = sharedContext();
    auto extents = [&](float strength, float rotation = 0.0f) {
        Material m;
        m.baseColorFactor = {1.0f, 1.0f, 1.0f, 1.0f};
        m.metallicFactor = 1.0f;
        m.roughnessFactor = 0.3f;
        m.anisotropyStrength = strength;
        m.anisotropyRotation = rotation;
        TestScene scene = sphereInSky(m, nullptr);
        scene.width = scene.height = 128;
        scene.lookAt({0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
        scene.lights.push_back(pointLight({0.0f, 0.0f, 4.0f}, 5000.0f, 50.0f));
        CapturedFrame frame = scene.render(context);
        float peak = 0.0f;
        for (uint32_t y = 0; y < frame.height; ++y)
            for (uint32_t x = 0; x < frame.width; ++x)
                peak = std::max(peak, hdrPixel(frame, x, y)[1]);
        uint32_t x0 = frame.width, x1 = 0, y0 = frame.height, y1 = 0;
        for (uint32_t y = 0; y < frame.height; ++y) {
            for (uint32_t x = 0; x < frame.width; ++x) {
                if (hdrPixel(frame, x, y)[1] < 0.1f * peak) continue;
                x0 = std::min(x0, x), x1 = std::max(x1, x);
                y0 = std::min(y0, y), y1 = std::max(y1, y);
            }
        }
        return std::pair<float, float>(float(x1 - x0 + 1), float(y1 - y0 + 1));
    };
    const auto [isoWidth, isoHeight] = extents(0.0f);
    const auto [anisoWidth, anisoHeight] = extents(0.9f);
    // anisotropyRotation a quarter turn: stretched along the bitangent (vertically) instead.
    const auto [turnedWidth, turnedHeight] = extents(0.9f, 0.5f * 3.14159265f);
    std::printf(
        "highlight extents (px): isotropic %.0f x %.0f, anisotropic %.0f x %.0f, rotated a "
        "quarter turn %.0f x %.0f\n",
        isoWidth, isoHeight, anisoWidth, anisoHeight, turnedWidth, turnedHeight);
    EXPECT_NEAR(isoWidth / isoHeight, 1.0f, 0.25f);
    EXPECT_GT(anisoWidth / anisoHeight, 1.5f);
    EXPECT_GT(anisoWidth, isoWidth);
    EXPECT_GT(turnedHeight / turnedWidth, 1.5f);
    EXPECT_EQ(context.validationMessages(), 0u);
}

// White furnace of the anisotropic lobe: a white metal sphere of strength 0.8 in a uniform
// white sky reflects the whole sky with multiple scattering, in the split sum (the LUT at the
// lobe's mean roughness) and in the reference (the lobe's own albedo from its samples), and
// never more: centre mean 0.97 to 1.01, every pixel under 1.01 (1.03 for the reference).
TEST(AnisotropicLobe, WhiteFurnaceReflectsTheSky) {
    GpuContext& context = sharedContext();
    std::shared_ptr<const Environment> sky = Environment::uniform(context, 1.0f);
    for (float roughness : {0.2f, 0.6f}) {
        Material m;
        m.baseColorFactor = {1.0f, 1.0f, 1.0f, 1.0f};
        m.metallicFactor = 1.0f;
        m.roughnessFactor = roughness;
        m.anisotropyStrength = 0.8f;
        for (IblMode mode : {IblMode::SplitSum, IblMode::Reference}) {
            RendererOptions options;
            options.ibl = mode;
            options.referenceSamples = 256;
            CapturedFrame frame = sphereInSky(m, sky).render(context, options);
            std::printf("%-10s anisotropic white metal roughness %.1f: centre %.4f, max %.4f\n",
                        iblModeName(mode), roughness, centreMean(frame), frameMax(frame));
            EXPECT_NEAR(centreMean(frame), 0.99, 0.02) << iblModeName(mode);
            EXPECT_LE(frameMax(frame), mode == IblMode::Reference ? 1.03f : 1.01f)
                << iblModeName(mode);
        }
    }
    EXPECT_EQ(context.validationMessages(), 0u);
}
