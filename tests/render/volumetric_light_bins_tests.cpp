// The volumetrics' per-workgroup light lists (passes/volumetrics/light_bins.h), on the CPU: every
// half-resolution pixel whose view ray meets a light's volume, and every froxel whose sample
// lies in it, finds the light in its workgroup's list, while lights elsewhere are left out.
// Pure logic, no device used.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "passes/volumetrics/light_bins.h"
#include "passes/volumetrics/light_proxies.h"

namespace candela::render {
namespace {

constexpr uint32_t kWidth = 96, kHeight = 64;

CameraView testCamera() {
    CameraView camera;
    camera.position = glm::vec3(0.5f, 1.0f, 2.0f);
    camera.view =
        glm::lookAt(camera.position, glm::vec3(0.0f, 0.0f, -6.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    camera.nearPlane = 0.05f;
    camera.projection =
        reverseZPerspective(glm::radians(60.0f), float(kWidth) / float(kHeight), camera.nearPlane);
    return camera;
}

// Point and spot lights around and behind the camera, some holding it, the same every run.
std::vector<LightInstance> scatteredLights() {
    std::mt19937 random(17);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::vector<LightInstance> lights;
    for (int i = 0; i < 160; ++i) {
        LightInstance l;
        l.light.type = i % 3 == 0 ? content::LightType::Spot : content::LightType::Point;
        l.light.attenuationRadius = 0.3f + 1.5f * (unit(random) + 1.0f);
        l.light.outerConeAngle = 0.2f + 0.5f * (unit(random) + 1.0f);
        l.position =
            glm::vec3(6.0f * unit(random), 4.0f * unit(random), -5.0f + 7.0f * unit(random));
        l.direction = glm::normalize(glm::vec3(unit(random), unit(random), unit(random)) +
                                     glm::vec3(0.0f, 0.0f, 0.01f));
        lights.push_back(l);
    }
    return lights;
}

// Whether P lies in the light's volume (its range sphere, cut by the cone for a spot).
bool insideVolume(const LightInstance& l, const glm::vec3& P) {
    const glm::vec3 d = P - l.position;
    const float distance = glm::length(d);
    if (distance > l.light.attenuationRadius) return false;
    if (l.light.type != content::LightType::Spot || distance < 1e-6f) return true;
    return glm::dot(d / distance, l.direction) >= std::cos(l.light.outerConeAngle);
}

// Light `light` is in bin `bin`'s list.
bool listed(const std::vector<uint32_t>& bins, uint32_t binCount, uint32_t bin, uint32_t light) {
    const auto first = bins.begin() + binCount + 1 + bins[bin];
    const auto last = bins.begin() + binCount + 1 + bins[bin + 1];
    return std::find(first, last, light) != last;  // plain lights first: not one sorted run
}

glm::vec3 nearPoint(const CameraView& camera, glm::vec2 ndc) {
    const glm::vec4 p = glm::inverse(camera.projection * camera.view) * glm::vec4(ndc, 1.0f, 1.0f);
    return glm::vec3(p) / p.w;
}

// The shaders walk a bin's plain lights with a body that has no shadow code, then the rest
// (light_bins.h): every list holds the same lights as without shadows, the plain ones first,
// each part in light order.
TEST(VolumetricLightBins, PlainLightsLeadEveryListInLightOrder) {
    const CameraView camera = testCamera();
    const std::vector<LightInstance> plain = scatteredLights();
    std::vector<LightInstance> lights = plain;
    for (size_t i = 0; i < lights.size(); i += 4)
        lights[i].light.castShadows = true;
    const std::vector<float> scales(lights.size(), 1.0f);
    const LightBinLayout layout = volumeTileLayout(kWidth, kHeight);
    const std::vector<uint32_t> bins = binLights(lights, scales, camera, layout);
    const std::vector<uint32_t> plainBins = binLights(plain, scales, camera, layout);
    const uint32_t binCount = layout.bins.x * layout.bins.y;
    uint32_t mixedBins = 0;
    for (uint32_t b = 0; b < binCount; ++b) {
        std::vector<uint32_t> list(bins.begin() + binCount + 1 + bins[b],
                                   bins.begin() + binCount + 1 + bins[b + 1]);
        const auto firstShadowed = std::find_if(
            list.begin(), list.end(), [&](uint32_t i) { return !isPlainMediumLight(lights[i]); });
        EXPECT_TRUE(std::none_of(firstShadowed, list.end(),
                                 [&](uint32_t i) { return isPlainMediumLight(lights[i]); }));
        EXPECT_TRUE(std::is_sorted(list.begin(), firstShadowed));
        EXPECT_TRUE(std::is_sorted(firstShadowed, list.end()));
        mixedBins += firstShadowed != list.begin() && firstShadowed != list.end();
        std::sort(list.begin(), list.end());
        const std::vector<uint32_t> expected(plainBins.begin() + binCount + 1 + plainBins[b],
                                             plainBins.begin() + binCount + 1 + plainBins[b + 1]);
        EXPECT_EQ(list, expected) << "bin " << b;
    }
    EXPECT_GT(mixedBins, 0u);  // the scene tests the order, not only the sets
}

TEST(VolumetricLightBins, EveryRayThatMeetsAVolumeFindsItsLightInItsTile) {
    const CameraView camera = testCamera();
    const std::vector<LightInstance> lights = scatteredLights();
    const std::vector<float> scales(lights.size(), 1.0f);
    const LightBinLayout layout = volumeTileLayout(kWidth, kHeight);
    const std::vector<uint32_t> bins = binLights(lights, scales, camera, layout);
    const uint32_t binCount = layout.bins.x * layout.bins.y;
    for (uint32_t b = 0; b < binCount; ++b) {
        EXPECT_TRUE(std::is_sorted(bins.begin() + binCount + 1 + bins[b],
                                   bins.begin() + binCount + 1 + bins[b + 1]));
    }
    uint32_t met = 0;
    for (uint32_t qy = 0; qy < layout.elements.y; ++qy) {
        for (uint32_t qx = 0; qx < layout.elements.x; ++qx) {
            // Half-resolution pixel q marches full pixel 2q's ray, 20 m deep here.
            const glm::vec2 ndc((float(2 * qx) + 0.5f) / kWidth * 2.0f - 1.0f,
                                (float(2 * qy) + 0.5f) / kHeight * 2.0f - 1.0f);
            const glm::vec3 direction = glm::normalize(nearPoint(camera, ndc) - camera.position);
            const uint32_t bin = (qy / 8) * layout.bins.x + qx / 8;
            for (uint32_t i = 0; i < lights.size(); ++i) {
                // Rays that miss the range sphere are skipped; the others are walked.
                const glm::vec3 toLight = lights[i].position - camera.position;
                const float along = glm::dot(toLight, direction);
                const float radius = lights[i].light.attenuationRadius;
                if (glm::dot(toLight, toLight) - along * along > radius * radius) continue;
                bool meets = false;
                for (float t = 0.0f; t < 20.0f && !meets; t += 0.02f)
                    meets = insideVolume(lights[i], camera.position + direction * t);
                if (!meets) continue;
                ++met;
                EXPECT_TRUE(listed(bins, binCount, bin, i))
                    << "light " << i << " missing from tile " << bin << " (pixel " << qx << ", "
                    << qy << ")";
            }
        }
    }
    EXPECT_GT(met, 1000u);
    // The lists leave lights out: fewer entries than every light in every tile.
    EXPECT_LT(bins.size() - binCount - 1, lights.size() * binCount / 2);
}

TEST(VolumetricLightBins, EveryFroxelInAVolumeFindsItsLightInItsCluster) {
    const CameraView camera = testCamera();
    const std::vector<LightInstance> lights = scatteredLights();
    std::vector<float> scales(lights.size(), 1.0f);
    scales[5] = 0.0f;  // lights no medium: listed nowhere
    const glm::uvec3 grid(12, 8, 64);
    const float nearDepth = camera.nearPlane, farDepth = 100.0f;
    const LightBinLayout layout = froxelClusterLayout(grid, nearDepth, farDepth);
    const std::vector<uint32_t> bins = binLights(lights, scales, camera, layout);
    const uint32_t binCount = layout.bins.x * layout.bins.y * layout.bins.z;
    auto boundary = [&](float b) {
        return b <= 0.0f ? 0.0f : nearDepth * std::pow(farDepth / nearDepth, b / float(grid.z));
    };
    uint32_t inside = 0;
    for (uint32_t z = 0; z < grid.z; ++z) {
        const float depth = 0.5f * (boundary(float(z)) + boundary(float(z + 1)));
        for (uint32_t y = 0; y < grid.y; ++y) {
            for (uint32_t x = 0; x < grid.x; ++x) {
                // The froxel's sample: on its centre's ray at its slice's middle view depth.
                const glm::vec2 ndc((float(x) + 0.5f) / float(grid.x) * 2.0f - 1.0f,
                                    (float(y) + 0.5f) / float(grid.y) * 2.0f - 1.0f);
                const glm::vec3 perDepth =
                    (nearPoint(camera, ndc) - camera.position) / camera.nearPlane;
                const glm::vec3 P = camera.position + perDepth * depth;
                const uint32_t bin = ((z / 4) * layout.bins.y + y / 4) * layout.bins.x + x / 4;
                for (uint32_t i = 0; i < lights.size(); ++i) {
                    if (!insideVolume(lights[i], P)) continue;
                    if (i == 5) {
                        EXPECT_FALSE(listed(bins, binCount, bin, i));
                        continue;
                    }
                    ++inside;
                    EXPECT_TRUE(listed(bins, binCount, bin, i))
                        << "light " << i << " missing from cluster " << bin;
                }
            }
        }
    }
    EXPECT_GT(inside, 100u);
    EXPECT_LT(bins.size() - binCount - 1, lights.size() * binCount / 4);
}

TEST(VolumetricLightBins, TheSunAndAVolumeHoldingTheCameraAreEverywhereAndOneBehindNowhere) {
    const CameraView camera = testCamera();
    std::vector<LightInstance> lights(3);
    lights[0].light.type = content::LightType::Directional;
    lights[1].position = camera.position + glm::vec3(0.2f, 0.0f, 0.0f);
    lights[1].light.attenuationRadius = 1.0f;
    lights[2].position = camera.position + glm::vec3(0.0f, 0.0f, 5.0f);  // behind it
    lights[2].light.attenuationRadius = 2.0f;
    const std::vector<float> scales(lights.size(), 1.0f);
    const LightBinLayout layout = volumeTileLayout(kWidth, kHeight);
    const std::vector<uint32_t> bins = binLights(lights, scales, camera, layout);
    const uint32_t binCount = layout.bins.x * layout.bins.y;
    for (uint32_t b = 0; b < binCount; ++b) {
        EXPECT_TRUE(listed(bins, binCount, b, 0));
        EXPECT_TRUE(listed(bins, binCount, b, 1));
        EXPECT_FALSE(listed(bins, binCount, b, 2));
    }
}

// The rasterised proxies' draws (light_proxies.h): a light whose volume is off screen gets no
// instance (no fragment); one wholly behind the wall is drawn with the depth test on (its
// front faces fail it: no fragment shades); one holding the camera draws its back faces
// untested; the sun goes to the full-screen pass and a light of no volumetric scale nowhere.
TEST(VolumetricLightProxies, DrawOnlyTheVolumesTheViewCanSee) {
    const CameraView camera = testCamera();
    auto point = [](const glm::vec3& position, float range) {
        LightInstance l;
        l.light.type = content::LightType::Point;
        l.light.attenuationRadius = range;
        l.position = position;
        return l;
    };
    std::vector<LightInstance> lights = {
        point(glm::vec3(0.0f, 0.5f, -4.0f), 1.0f),   // 0: in view, the camera outside
        point(glm::vec3(0.5f, 1.0f, 12.0f), 3.0f),   // 1: behind the camera (off screen)
        point(glm::vec3(40.0f, 1.0f, -6.0f), 2.0f),  // 2: far beside the view
        point(glm::vec3(0.6f, 1.1f, 1.5f), 1.0f),    // 3: holds the camera
        point(glm::vec3(0.0f, 0.5f, -4.0f), 1.0f),   // 4: volumetric 0
    };
    LightInstance spot = point(glm::vec3(0.5f, 1.0f, 4.0f), 10.0f);  // 5: its cone holds it
    spot.light.type = content::LightType::Spot;
    spot.light.outerConeAngle = 0.4f;
    spot.direction = glm::vec3(0.0f, 0.0f, -1.0f);
    lights.push_back(spot);
    LightInstance wide = spot;  // 6: a cone of 80 degrees draws the sphere
    wide.light.outerConeAngle = glm::radians(80.0f);
    wide.position = glm::vec3(-1.0f, 0.0f, -5.0f);
    wide.light.attenuationRadius = 1.0f;
    lights.push_back(wide);
    LightInstance sun;
    sun.light.type = content::LightType::Directional;
    lights.push_back(sun);                                           // 7
    LightInstance rect = point(glm::vec3(0.0f, 1.0f, -3.0f), 2.0f);  // 8: a hemisphere
    rect.light.type = content::LightType::Rect;
    rect.direction = glm::vec3(0.0f, 0.0f, 1.0f);  // facing the camera, 4.5 m away
    lights.push_back(rect);
    LightInstance away = rect;  // 9: its sphere holds the camera, which is behind it
    away.position = glm::vec3(0.6f, 1.1f, 0.5f);
    away.direction = glm::vec3(0.0f, 0.0f, -1.0f);
    lights.push_back(away);
    LightInstance facing = away;  // 10: the same facing the camera holds it
    facing.direction = glm::vec3(0.0f, 0.0f, 1.0f);
    lights.push_back(facing);
    std::vector<float> scales(lights.size(), 1.0f);
    scales[4] = 0.0f;
    const LightProxies proxies = buildLightProxies(lights, scales, camera, kWidth, kHeight);
    ASSERT_EQ(proxies.fullScreen, 1u);
    EXPECT_EQ(proxies.instances[0], 7u);
    // Which draw each light is in (none: -1).
    auto drawOf = [&](uint32_t light) -> int {
        for (size_t d = 0; d < proxies.draws.size(); ++d) {
            const LightProxyDraw& draw = proxies.draws[d];
            for (uint32_t k = draw.firstInstance; k < draw.firstInstance + draw.instanceCount; ++k)
                if (proxies.instances[k] == light) return int(d);
        }
        return -1;
    };
    EXPECT_EQ(drawOf(1), -1) << "behind the camera";
    EXPECT_EQ(drawOf(2), -1) << "beside the view";
    EXPECT_EQ(drawOf(4), -1) << "no volumetric scale";
    ASSERT_GE(drawOf(0), 0);
    EXPECT_FALSE(proxies.draws[drawOf(0)].holdsCamera);
    EXPECT_EQ(proxies.draws[drawOf(0)].kind, LightProxyKind::Sphere);
    ASSERT_GE(drawOf(3), 0);
    EXPECT_TRUE(proxies.draws[drawOf(3)].holdsCamera);
    ASSERT_GE(drawOf(5), 0);
    EXPECT_TRUE(proxies.draws[drawOf(5)].holdsCamera);
    EXPECT_EQ(proxies.draws[drawOf(5)].kind, LightProxyKind::Cone);
    ASSERT_GE(drawOf(6), 0);
    EXPECT_EQ(proxies.draws[drawOf(6)].kind, LightProxyKind::Sphere);
    // Rect and disk lights light the half-space in front of them only.
    for (uint32_t one : {8u, 9u, 10u}) {
        ASSERT_GE(drawOf(one), 0) << one;
        EXPECT_EQ(proxies.draws[drawOf(one)].kind, LightProxyKind::Hemisphere) << one;
        EXPECT_TRUE(proxies.draws[drawOf(one)].areaLights) << one;
    }
    EXPECT_FALSE(proxies.draws[drawOf(8)].holdsCamera);
    EXPECT_FALSE(proxies.draws[drawOf(9)].holdsCamera) << "the camera is behind the emitter";
    EXPECT_TRUE(proxies.draws[drawOf(10)].holdsCamera);
    // One draw per group: every instance once.
    size_t instanced = proxies.fullScreen;
    for (const LightProxyDraw& draw : proxies.draws)
        instanced += draw.instanceCount;
    EXPECT_EQ(instanced, proxies.instances.size());
    EXPECT_EQ(proxies.instances.size(), 8u);
}

}  // namespace
// Issue 41: the froxel lighting's per-cluster cap keeps, in each crowded cluster, the plain
// lights that put the most light into its air, and every light that is not plain; lists keep
// their order (plain first, each part ascending) and clusters under the cap are untouched.
TEST(VolumetricLightBins, ACappedClusterKeepsItsStrongestPlainLightsAndEveryOther) {
    const CameraView camera = testCamera();
    std::vector<LightInstance> lights = scatteredLights();
    lights[7].light.castShadows = true;  // not plain: never dropped
    lights[11].light.type = content::LightType::Rect;
    for (LightInstance& l : lights)
        l.light.lumens = 500.0f;
    const std::vector<float> scales(lights.size(), 1.0f);
    const LightBinLayout layout = froxelClusterLayout(glm::uvec3(12, 8, 64), 0.05f, 100.0f);
    const std::vector<uint32_t> bins = binLights(lights, scales, camera, layout);
    const uint32_t binCount = layout.bins.x * layout.bins.y * layout.bins.z;
    constexpr uint32_t kCap = 6;
    const std::vector<uint32_t> capped = capPlainLights(bins, lights, scales, camera, layout, kCap);
    EXPECT_EQ(capPlainLights(bins, lights, scales, camera, layout, 0), bins);  // 0: no cap
    uint32_t crowded = 0;
    for (uint32_t b = 0; b < binCount; ++b) {
        const std::vector<uint32_t> before(bins.begin() + binCount + 1 + bins[b],
                                           bins.begin() + binCount + 1 + bins[b + 1]);
        const std::vector<uint32_t> after(capped.begin() + binCount + 1 + capped[b],
                                          capped.begin() + binCount + 1 + capped[b + 1]);
        const auto plainCount = [&](const std::vector<uint32_t>& list) {
            return uint32_t(std::count_if(list.begin(), list.end(), [&](uint32_t l) {
                return isPlainMediumLight(lights[l]);
            }));
        };
        const uint32_t plainBefore = plainCount(before);
        if (plainBefore <= kCap) {
            EXPECT_EQ(after, before) << "cluster " << b;
            continue;
        }
        ++crowded;
        EXPECT_EQ(plainCount(after), kCap) << "cluster " << b;
        EXPECT_EQ(after.size(), before.size() - (plainBefore - kCap)) << "cluster " << b;
        // A subsequence of the old list: order kept, only plain lights gone.
        EXPECT_TRUE(std::includes(before.begin(), before.begin() + plainBefore, after.begin(),
                                  after.begin() + kCap));
        EXPECT_TRUE(std::equal(after.begin() + kCap, after.end(), before.begin() + plainBefore));
    }
    EXPECT_GT(crowded, 0u);

    // Three lights in one place: a cap of one keeps the brightest wherever they are listed.
    std::vector<LightInstance> three(3);
    for (uint32_t i = 0; i < 3; ++i) {
        three[i].position = glm::vec3(0.0f, 0.0f, -4.0f);
        three[i].light.attenuationRadius = 3.0f;
        three[i].light.lumens = i == 1 ? 1000.0f : 100.0f;
    }
    const std::vector<float> ones(3, 1.0f);
    const std::vector<uint32_t> threeBins = binLights(three, ones, camera, layout);
    const std::vector<uint32_t> one = capPlainLights(threeBins, three, ones, camera, layout, 1);
    uint32_t listedBins = 0;
    for (uint32_t b = 0; b < binCount; ++b) {
        if (threeBins[b + 1] == threeBins[b]) continue;
        ++listedBins;
        ASSERT_EQ(one[b + 1] - one[b], 1u);
        EXPECT_EQ(one[binCount + 1 + one[b]], 1u);
    }
    EXPECT_GT(listedBins, 0u);
}

}  // namespace candela::render
