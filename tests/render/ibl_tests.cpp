// Image-based lighting (issue 6): the environment BRDF LUT against a double-precision
// integration of eq. 8, white furnaces, bad environment files, and the disk cache.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "candela/content/exr_image.h"
#include "candela/render/environment.h"
#include "ibl/environment_brdf_lut.h"
#include "ibl/environment_cache.h"
#include "ibl_test_support.h"
#include "test_scene.h"
#include "vk/image_transfer.h"

using namespace candela::render;
using namespace candela::render::test;
using candela::content::Diagnostics;
using candela::content::makeSphere;

namespace {

constexpr double kPi = std::numbers::pi;

// Eq. 8 in double precision, written here independently of the shader: a Fibonacci lattice
// (4181 points, generator 2584; the shader uses 1024 Hammersley points) on the unit square
// mapped to GGX visible normals (Heitz 2018), whose estimator F G(V, L) / G1(V) is smooth up
// to the horizon; plain D NoH sampling needs ~1e5 points at grazing NoV. Checked against a
// 1024^2 midpoint rule while writing this test: within 3.3e-4 everywhere probed. Same terms
// as the engine: eq. 3, Schlick-Smith G with k = alpha / 2 (eq. 4) or, `correlated`, exact
// height-correlated Smith G2 = 1 / (1 + Lambda(V) + Lambda(L)); pow5 Fresnel split.
std::pair<double, double> integrateEq8(double roughness, double NoV, bool correlated = false) {
    constexpr int kPoints = 4181;
    constexpr int kGenerator = 2584;
    const double alpha = roughness * roughness;
    const double a2 = alpha * alpha;
    const double k = alpha / 2.0;
    const glm::dvec3 V(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
    const glm::dvec3 Vh = glm::normalize(glm::dvec3(alpha * V.x, 0.0, V.z));
    const glm::dvec3 T1 = Vh.x > 0.0 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    const glm::dvec3 T2 = glm::cross(Vh, T1);
    const double g1sV = NoV / (NoV * (1.0 - k) + k);
    const double g1V = 2.0 * NoV / (NoV + std::sqrt(a2 + (1.0 - a2) * NoV * NoV));
    double a = 0.0, b = 0.0;
    for (int i = 0; i < kPoints; ++i) {
        const double r = std::sqrt((i + 0.5) / kPoints);
        const double phi = 2.0 * kPi * std::fmod((double(i) * kGenerator + 0.5) / kPoints, 1.0);
        const double t1 = r * std::cos(phi);
        const double s = 0.5 * (1.0 + Vh.z);
        const double t2 = (1.0 - s) * std::sqrt(1.0 - t1 * t1) + s * r * std::sin(phi);
        const glm::dvec3 Nh =
            t1 * T1 + t2 * T2 + std::sqrt(std::max(0.0, 1.0 - t1 * t1 - t2 * t2)) * Vh;
        const glm::dvec3 H =
            glm::normalize(glm::dvec3(alpha * Nh.x, alpha * Nh.y, std::max(Nh.z, 1e-12)));
        const double VoH = glm::dot(V, H);
        const double NoL = 2.0 * VoH * H.z - V.z;
        if (NoL <= 0.0 || VoH <= 0.0) continue;
        // Lambda(x) = (sqrt(1 + a2 tan^2) - 1) / 2, tan^2 = 1 / cos^2 - 1.
        auto lambda = [&](double c) {
            return 0.5 * (std::sqrt(1.0 + a2 * (1.0 / (c * c) - 1.0)) - 1.0);
        };
        const double weight = correlated ? (1.0 / (1.0 + lambda(NoV) + lambda(NoL))) / g1V
                                         : g1sV * (NoL / (NoL * (1.0 - k) + k)) / g1V;
        const double fc = std::pow(1.0 - VoH, 5.0);
        a += (1.0 - fc) * weight;
        b += fc * weight;
    }
    return {a / kPoints, b / kPoints};
}

candela::content::Material metal(float roughness) {
    candela::content::Material m;
    m.baseColorFactor = {1.0f, 1.0f, 1.0f, 1.0f};
    m.metallicFactor = 1.0f;
    m.roughnessFactor = roughness;
    return m;
}

struct CentreStats {
    float min = 1e30f, max = -1e30f;
    double mean = 0.0;
};

// Over the central 16x16 pixels, all channels.
CentreStats centreStats(const CapturedFrame& frame) {
    CentreStats s;
    int n = 0;
    for (uint32_t y = frame.height / 2 - 8; y < frame.height / 2 + 8; ++y) {
        for (uint32_t x = frame.width / 2 - 8; x < frame.width / 2 + 8; ++x) {
            for (int c = 0; c < 3; ++c) {
                float v = hdrPixel(frame, x, y)[c];
                s.min = std::min(s.min, v);
                s.max = std::max(s.max, v);
                s.mean += v;
                ++n;
            }
        }
    }
    s.mean /= n;
    return s;
}

}  // namespace

// Both pairs of the LUT: Schlick-Smith (the UE4 BRDF) and height-correlated Smith (the
// energy-conserving BRDF, whose scale + bias is also the directional albedo E_ss that the
// multiple-scattering compensation divides by).
TEST(EnvironmentBrdfLut, MatchesDoublePrecisionEq8AtEveryTexel) {
    GpuContext& context = sharedContext();
    EnvironmentBrdfLut lut(context);
    const uint32_t n = EnvironmentBrdfLut::kSize;
    for (bool correlated : {false, true}) {
        double worst = 0.0;
        uint32_t worstX = 0, worstY = 0;
        for (uint32_t y = 0; y < n; ++y) {
            for (uint32_t x = 0; x < n; ++x) {
                // The correlated pair's grid: NoV = (x / (n - 1))^2 (from 1e-7, as the shader
                // clamps), roughness = y / (n - 1) from kMinRoughness 0.02 (ibl.glsl
                // correlatedLutTexelParameters, integrateEnvironmentBrdfCorrelated).
                const double u = double(x) / (n - 1);
                auto [a, b] = correlated ? integrateEq8(std::max(double(y) / (n - 1), 0.02),
                                                        std::max(u * u, 1e-7), true)
                                         : integrateEq8((y + 0.5) / n, (x + 0.5) / n);
                uint32_t texel = y * n + x;
                uint32_t packed =
                    correlated ? lut.packedCorrelated(texel) : lut.packedSchlick(texel);
                double gpuA = (packed & 0xFFFFu) / 65535.0;
                double gpuB = (packed >> 16) / 65535.0;
                double error = std::max(std::abs(gpuA - a), std::abs(gpuB - b));
                if (error > worst) {
                    worst = error;
                    worstX = x;
                    worstY = y;
                }
            }
        }
        std::printf(
            "LUT %ux%u (%s), %u samples/texel, built in %.1f ms: worst |error| %.2e at "
            "texel (%u, %u)\n",
            n, n, correlated ? "height-correlated Smith" : "Schlick-Smith",
            EnvironmentBrdfLut::kSampleCount, lut.buildMs(), worst, worstX, worstY);
        EXPECT_LE(worst, 2e-3) << (correlated ? "height-correlated" : "Schlick-Smith");
    }
    EXPECT_EQ(context.validationMessages(), 0u);
}

namespace {

std::vector<uint8_t> lutImageBytes(GpuContext& context, const EnvironmentBrdfLut& lut) {
    return readImage(context, lut.image(), 8, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

std::string fileBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

bool anyWarningContains(const std::vector<std::string>& warnings, const std::string& text) {
    return std::any_of(warnings.begin(), warnings.end(),
                       [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

}  // namespace

// The first renderer builds the LUT and writes it to the cache folder; a renderer of this
// process reuses its texels, and another process (here: another folder holding the same
// file) reads them from disk. Every way yields the freshly built image, texel for texel.
TEST(EnvironmentBrdfLutCache, LoadsFromDiskAndProcessEqualToTheBuiltLut) {
    GpuContext& context = sharedContext();
    const EnvironmentBrdfLut built(context);
    const std::vector<uint8_t> expected = lutImageBytes(context, built);
    const std::filesystem::path dir = freshDirectory("brdf_lut_cache");
    std::vector<std::string> warnings;

    std::unique_ptr<EnvironmentBrdfLut> first =
        EnvironmentBrdfLut::loadOrBuild(context, dir, warnings);
    EXPECT_EQ(first->source(), EnvironmentBrdfLut::Source::Built);
    EXPECT_TRUE(std::filesystem::is_regular_file(EnvironmentBrdfLut::cachePath(dir)));
    std::unique_ptr<EnvironmentBrdfLut> again =
        EnvironmentBrdfLut::loadOrBuild(context, dir, warnings);
    EXPECT_EQ(again->source(), EnvironmentBrdfLut::Source::ProcessCache);

    const std::filesystem::path other = freshDirectory("brdf_lut_cache_copy");
    std::filesystem::copy_file(EnvironmentBrdfLut::cachePath(dir),
                               EnvironmentBrdfLut::cachePath(other));
    std::unique_ptr<EnvironmentBrdfLut> fromDisk =
        EnvironmentBrdfLut::loadOrBuild(context, other, warnings);
    EXPECT_EQ(fromDisk->source(), EnvironmentBrdfLut::Source::DiskCache);
    std::printf(
        "BRDF LUT: built in %.1f ms, loaded from disk in %.2f ms, from the process in %.2f ms\n",
        first->buildMs(), fromDisk->buildMs(), again->buildMs());
    EXPECT_TRUE(warnings.empty()) << warnings.front();

    for (const EnvironmentBrdfLut* lut : {first.get(), again.get(), fromDisk.get()}) {
        EXPECT_EQ(std::memcmp(lut->packedTexels(), built.packedTexels(),
                              size_t(EnvironmentBrdfLut::kSize) * EnvironmentBrdfLut::kSize * 8),
                  0)
            << lut->sourceName();
        EXPECT_EQ(lutImageBytes(context, *lut), expected) << lut->sourceName();
    }
    EXPECT_EQ(context.validationMessages(), 0u);
}

// Issue 44: an environment entry whose payload held NaN or Inf under a valid checksum lit every
// later run with NaN until the cache was deleted. Its content is checked now: such an entry is
// refused (and the caller recomputes and rewrites it), a finite one is read back.
TEST(EnvironmentCache, AnEntryWhosePayloadIsNotFiniteIsRefused) {
    const std::filesystem::path dir = freshDirectory("environment_cache_nonfinite");
    CachedEnvironment entry;
    entry.sizes = environmentSizesFor(16);
    entry.cube.assign(64, 0);
    entry.prefiltered.assign(64, 0);
    entry.irradianceSh.assign(9 * 16, 0);
    const uint16_t halfOne = 0x3C00, halfInf = 0x7C00, halfNaN = 0x7E00;
    std::memcpy(entry.cube.data(), &halfOne, 2);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    struct Case {
        const char* name;
        std::function<void(CachedEnvironment&)> damage;
        bool refused;
    };
    const Case cases[] = {
        {"finite", [](CachedEnvironment&) {}, false},
        {"cube_inf", [&](CachedEnvironment& e) { std::memcpy(e.cube.data() + 10, &halfInf, 2); },
         true},
        {"prefiltered_nan",
         [&](CachedEnvironment& e) { std::memcpy(e.prefiltered.data() + 62, &halfNaN, 2); }, true},
        {"sh_nan", [&](CachedEnvironment& e) { std::memcpy(e.irradianceSh.data() + 4, &nan, 4); },
         true},
    };
    for (const Case& c : cases) {
        CachedEnvironment damaged = entry;
        c.damage(damaged);
        const std::filesystem::path path = dir / (std::string(c.name) + ".bin");
        ASSERT_EQ(writeCachedEnvironment(path, damaged), "") << c.name;
        std::string problem;
        const std::optional<CachedEnvironment> read = readCachedEnvironment(path, problem);
        EXPECT_EQ(!read.has_value(), c.refused) << c.name;
        if (c.refused) {
            EXPECT_EQ(problem, "its payload holds NaN or Inf") << c.name;
        } else {
            ASSERT_TRUE(read) << problem;
            EXPECT_EQ(read->cube, damaged.cube);
        }
    }
}

// A flipped payload byte (checksum) or a truncated file is noticed, warned about, rebuilt
// and rewritten whole.
TEST(EnvironmentBrdfLutCache, CorruptOrTruncatedEntryIsRebuiltWithAWarning) {
    GpuContext& context = sharedContext();
    const std::filesystem::path good = freshDirectory("brdf_lut_good");
    std::vector<std::string> warnings;
    std::unique_ptr<EnvironmentBrdfLut> built =
        EnvironmentBrdfLut::loadOrBuild(context, good, warnings);
    const std::string original = fileBytes(EnvironmentBrdfLut::cachePath(good));
    ASSERT_GT(original.size(), 1000u);

    struct Damage {
        const char* name;
        std::string bytes;
        const char* problem;
    };
    std::string flipped = original;
    flipped[original.size() / 2] ^= 0x40;
    const Damage damages[] = {
        {"corrupt", flipped, "checksum mismatch"},
        {"truncated", original.substr(0, original.size() - 100), "wrong size"}};
    for (const Damage& d : damages) {
        const std::filesystem::path dir = freshDirectory(std::string("brdf_lut_") + d.name);
        const std::filesystem::path path = EnvironmentBrdfLut::cachePath(dir);
        writeBytes(path, d.bytes);
        warnings.clear();
        std::unique_ptr<EnvironmentBrdfLut> lut =
            EnvironmentBrdfLut::loadOrBuild(context, dir, warnings);
        EXPECT_EQ(lut->source(), EnvironmentBrdfLut::Source::Built) << d.name;
        EXPECT_TRUE(anyWarningContains(warnings, d.problem)) << d.name;
        EXPECT_TRUE(anyWarningContains(warnings, path.string())) << d.name;
        EXPECT_EQ(fileBytes(path), original) << d.name << ": the entry is rewritten";
        EXPECT_EQ(lutImageBytes(context, *lut), lutImageBytes(context, *built)) << d.name;
    }
    EXPECT_EQ(context.validationMessages(), 0u);
}

// A cache folder that cannot be created (a file stands in its way) costs a warning and the
// build, never the LUT.
TEST(EnvironmentBrdfLutCache, UnwritableCacheFolderStillBuildsTheLut) {
    GpuContext& context = sharedContext();
    const std::filesystem::path blocker = freshDirectory("brdf_lut_blocked") / "not_a_folder";
    writeBytes(blocker, "x");
    std::vector<std::string> warnings;
    std::unique_ptr<EnvironmentBrdfLut> lut =
        EnvironmentBrdfLut::loadOrBuild(context, blocker / "cache", warnings);
    EXPECT_EQ(lut->source(), EnvironmentBrdfLut::Source::Built);
    EXPECT_TRUE(anyWarningContains(warnings, "not written"));
    const EnvironmentBrdfLut built(context);
    EXPECT_EQ(lutImageBytes(context, *lut), lutImageBytes(context, built));
    EXPECT_EQ(context.validationMessages(), 0u);
}

TEST(IblFurnace, WhiteLambertSphereInUniformSkyRendersRadianceOne) {
    GpuContext& context = sharedContext();
    std::shared_ptr<const Environment> sky = Environment::uniform(context, 1.0f);
    for (IblMode mode : kIblModes) {
        RendererOptions options;
        options.ibl = mode;
        options.referenceSamples = 1024;
        TestScene scene = sphereInSky(lambertWhite(), sky);
        CentreStats s = centreStats(scene.render(context, options));
        std::printf("%-10s white Lambert sphere: radiance %.5f .. %.5f\n", iblModeName(mode), s.min,
                    s.max);
        EXPECT_NEAR(s.min, 1.0f, 0.01f) << iblModeName(mode);
        EXPECT_NEAR(s.max, 1.0f, 0.01f) << iblModeName(mode);
    }
    EXPECT_EQ(context.validationMessages(), 0u);
}

TEST(IblFurnace, MetalSpheresNeverGainEnergyAndReportSingleScatteringLoss) {
    GpuContext& context = sharedContext();
    std::shared_ptr<const Environment> sky = Environment::uniform(context, 1.0f);
    for (IblMode mode : kIblModes) {
        RendererOptions options;
        // Karis 2013, "Real Shading in Unreal Engine 4": single scattering, Schlick-Smith.
        options.brdf = BrdfModel::Ue4;
        options.ibl = mode;
        options.referenceSamples = 1024;
        for (float roughness : {0.0f, 0.25f, 0.5f, 0.75f, 1.0f}) {
            TestScene scene = sphereInSky(metal(roughness), sky);
            CentreStats s = centreStats(scene.render(context, options));
            std::printf("%-10s metal roughness %.2f: radiance %.4f .. %.4f (energy lost %.1f%%)\n",
                        iblModeName(mode), roughness, s.min, s.max, 100.0 * (1.0 - s.mean));
            // fp16 cubes and a 16-bit LUT round: 2e-3 of headroom. The reference's Monte Carlo
            // estimate of a uniform sky is noisier.
            EXPECT_LE(s.max, mode == IblMode::Reference ? 1.01f : 1.002f)
                << iblModeName(mode) << " roughness " << roughness;
            if (roughness == 1.0f) {
                // Single-scattering GGX loses energy at high roughness: the sphere is visibly
                // darker than the sky (this also proves the sphere was drawn).
                EXPECT_LT(s.mean, 0.99) << iblModeName(mode);
            }
        }
    }
    EXPECT_EQ(context.validationMessages(), 0u);
}

// Issue 26's furnace: with multiple-scattering compensation (the default BRDF) white metal
// spheres of roughness 0.25 to 1 reflect 0.95 to 1.01 of a uniform white sky in every IBL
// mode; single scattering (--brdf ue4) reflects 0.99 / 0.89 / 0.60 / 0.31 of it.
TEST(IblFurnace, EnergyConservingMetalSpheresReflectTheWholeSky) {
    GpuContext& context = sharedContext();
    std::shared_ptr<const Environment> sky = Environment::uniform(context, 1.0f);
    for (IblMode mode : kIblModes) {
        RendererOptions options;
        options.brdf = BrdfModel::EnergyConserving;
        options.ibl = mode;
        options.referenceSamples = 1024;
        for (float roughness : {0.0f, 0.25f, 0.5f, 0.75f, 1.0f}) {
            TestScene scene = sphereInSky(metal(roughness), sky);
            CentreStats s = centreStats(scene.render(context, options));
            std::printf(
                "%-10s energy-conserving metal roughness %.2f: radiance %.4f .. %.4f "
                "(mean %.4f)\n",
                iblModeName(mode), roughness, s.min, s.max, s.mean);
            EXPECT_GE(s.mean, 0.95) << iblModeName(mode) << " roughness " << roughness;
            EXPECT_LE(s.mean, 1.01) << iblModeName(mode) << " roughness " << roughness;
            EXPECT_LE(s.max, 1.01f) << iblModeName(mode) << " roughness " << roughness;
        }
    }
    EXPECT_EQ(context.validationMessages(), 0u);
}

// The multiple-scattering term is tinted by the metal's own Fresnel (F_ms, F_avg): a gold
// sphere gets brighter without turning grey. Each further bounce tints the light again, so
// the colour deepens: saturation rises and the hue moves a few degrees toward the strongest
// channel (measured: 35.2 -> 30.2 degrees, saturation 0.71 -> 0.79); a grey compensation
// would lower the saturation instead. No channel exceeds the sky.
TEST(IblFurnace, CompensatedColouredMetalKeepsItsHue) {
    GpuContext& context = sharedContext();
    std::shared_ptr<const Environment> sky = Environment::uniform(context, 1.0f);
    candela::content::Material gold = metal(0.75f);
    gold.baseColorFactor = {1.0f, 0.71f, 0.29f, 1.0f};
    auto meanColour = [&](BrdfModel brdf) {
        RendererOptions options;
        options.brdf = brdf;
        CapturedFrame frame = sphereInSky(gold, sky).render(context, options);
        glm::dvec3 sum(0.0);
        for (uint32_t y = frame.height / 2 - 8; y < frame.height / 2 + 8; ++y) {
            for (uint32_t x = frame.width / 2 - 8; x < frame.width / 2 + 8; ++x) {
                for (int c = 0; c < 3; ++c)
                    sum[c] += hdrPixel(frame, x, y)[c];
            }
        }
        return sum / 256.0;
    };
    // Hue and saturation of HSV, in degrees and [0, 1].
    auto hueOf = [](glm::dvec3 c) {
        const double maxC = std::max({c.r, c.g, c.b}), minC = std::min({c.r, c.g, c.b});
        const double h = 60.0 * (c.g - c.b) / (maxC - minC);  // red is the largest here
        return std::pair<double, double>{h, (maxC - minC) / maxC};
    };
    const glm::dvec3 single = meanColour(BrdfModel::Ue4);
    const glm::dvec3 multiple = meanColour(BrdfModel::EnergyConserving);
    auto [hueSingle, saturationSingle] = hueOf(single);
    auto [hueMultiple, saturationMultiple] = hueOf(multiple);
    std::printf(
        "gold, roughness 0.75: single (%.4f %.4f %.4f) hue %.2f sat %.3f; compensated "
        "(%.4f %.4f %.4f) hue %.2f sat %.3f\n",
        single.r, single.g, single.b, hueSingle, saturationSingle, multiple.r, multiple.g,
        multiple.b, hueMultiple, saturationMultiple);
    ASSERT_GT(single.r, single.b);
    EXPECT_GT(multiple.r, single.r * 1.05);  // the compensation did something
    EXPECT_NEAR(hueMultiple, hueSingle, 6.0);
    EXPECT_GE(saturationMultiple, saturationSingle);
    EXPECT_LE(std::max({multiple.r, multiple.g, multiple.b}), 1.01);
    EXPECT_EQ(context.validationMessages(), 0u);
}

TEST(IblEnvironment, BadFilesGiveAClearErrorAndTheNeutralSky) {
    GpuContext& context = sharedContext();
    std::filesystem::path dir = freshDirectory("bad");
    std::filesystem::path empty = dir / "empty.exr";
    std::ofstream(empty).close();
    std::filesystem::path garbage = dir / "garbage.exr";
    std::ofstream(garbage) << "this is not an OpenEXR file";
    std::filesystem::path truncated = dir / "truncated.exr";
    {
        std::ifstream in(sharedAsset("env/StageEnvLatLong.exr"), std::ios::binary);
        std::vector<char> bytes((std::istreambuf_iterator<char>(in)), {});
        std::ofstream(truncated, std::ios::binary)
            .write(bytes.data(), std::streamsize(bytes.size() / 3));
    }
    std::vector<std::filesystem::path> files = {dir / "missing.exr", empty, garbage, truncated};
    for (const char* name : {"bad/exr/NULL_pointer.exr", "bad/exr/memory_DOS_1.exr",
                             "bad/exr/openexr_2.5.1_null_deref_error.exr"}) {
        files.push_back(sharedAsset(name));
    }
    EnvironmentCacheOptions cache{dir / "cache"};
    for (const std::filesystem::path& file : files) {
        Diagnostics diagnostics;
        std::unique_ptr<Environment> env = Environment::load(context, file, diagnostics, cache);
        ASSERT_NE(env, nullptr);
        EXPECT_TRUE(env->stats().fallback) << file;
        EXPECT_TRUE(diagnostics.hasErrors()) << file;
        EXPECT_TRUE(diagnostics.mentions(file.string())) << diagnostics.toString();
        EXPECT_TRUE(diagnostics.mentions("neutral uniform sky")) << diagnostics.toString();
    }
    // The neutral sky lights a scene like any other.
    Diagnostics diagnostics;
    TestScene scene = sphereInSky(lambertWhite(), Environment::load(context, garbage, diagnostics));
    CentreStats s = centreStats(scene.render(context));
    EXPECT_NEAR(s.mean, Environment::kFallbackRadiance, Environment::kFallbackRadiance * 0.01);
    EXPECT_EQ(context.validationMessages(), 0u);
}

TEST(IblEnvironment, SecondLoadReadsTheCacheAndACorruptEntryIsRebuilt) {
    GpuContext& context = sharedContext();
    EnvironmentCacheOptions cache{freshDirectory("cache")};
    const std::filesystem::path exr = sharedAsset("env/StageEnvLatLong.exr");
    auto load = [&](Diagnostics& diagnostics) {
        return Environment::load(context, exr, diagnostics, cache);
    };
    Diagnostics first, second, third;
    std::unique_ptr<Environment> computed = load(first);
    std::unique_ptr<Environment> cached = load(second);
    EXPECT_FALSE(computed->stats().fromCache);
    EXPECT_TRUE(cached->stats().fromCache);
    EXPECT_EQ(cached->stats().precomputeMs, 0.0);
    EXPECT_FALSE(first.hasErrors()) << first.toString();
    // The cache holds exactly what the device computed.
    EXPECT_EQ(
        readImage(context, computed->prefiltered(), 8, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL),
        readImage(context, cached->prefiltered(), 8, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL));
    EXPECT_EQ(std::memcmp(computed->irradianceSh().mapped(), cached->irradianceSh().mapped(), 144),
              0);

    // Truncate the entry: it is ignored with a warning, recomputed and rewritten.
    std::filesystem::path entry = *std::filesystem::directory_iterator(cache.directory);
    std::filesystem::resize_file(entry, std::filesystem::file_size(entry) / 2);
    std::unique_ptr<Environment> rebuilt = load(third);
    EXPECT_FALSE(rebuilt->stats().fromCache);
    EXPECT_TRUE(third.mentions("ignoring cache entry")) << third.toString();
    Diagnostics fourth;
    EXPECT_TRUE(load(fourth)->stats().fromCache);

    // A FIFO in place of the entry (issue 22: readers check the type before opening) is
    // ignored with a warning instead of blocking the open, and the sky is recomputed.
    std::filesystem::remove(entry);
    ASSERT_EQ(::mkfifo(entry.c_str(), 0600), 0);
    Diagnostics fifth;
    EXPECT_FALSE(load(fifth)->stats().fromCache);
    EXPECT_TRUE(fifth.mentions("not a regular file")) << fifth.toString();
    EXPECT_EQ(context.validationMessages(), 0u);
}

// Blended (glTF BLEND) surfaces are shaded by the forward pass: they get the same ambient
// light. A half-transparent white Lambert sphere in the uniform sky reflects radiance 1 and
// lets half the sky through: 0.5 x 1 + 0.5 x 1 = 1. Without ambient it would show 0.5.
TEST(IblFurnace, BlendedLambertSphereGetsTheSameAmbientLight) {
    GpuContext& context = sharedContext();
    std::shared_ptr<const Environment> sky = Environment::uniform(context, 1.0f);
    candela::content::Material glass = lambertWhite();
    glass.baseColorFactor[3] = 0.5f;
    glass.alphaMode = candela::content::AlphaMode::Blend;
    for (IblMode mode : {IblMode::SplitSum, IblMode::Mobile}) {
        RendererOptions options;
        options.ibl = mode;
        RendererStats stats;
        TestScene scene = sphereInSky(glass, sky);
        CentreStats s = centreStats(scene.render(context, options, &stats));
        std::printf("%-10s blended white Lambert sphere: radiance %.5f .. %.5f\n",
                    iblModeName(mode), s.min, s.max);
        EXPECT_NEAR(s.min, 1.0f, 0.01f) << iblModeName(mode);
        EXPECT_NEAR(s.max, 1.0f, 0.01f) << iblModeName(mode);
    }
    EXPECT_EQ(context.validationMessages(), 0u);
}
