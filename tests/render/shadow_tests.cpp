// Rendered shadows (issue 14) against a CPU ray cast of the same scene: a box over a floor
// under a sun, a spot and a point light; bias (no acne on a 60 degree slope, no gap under a
// box on the floor); cascades that do not shimmer when the camera moves; clustered and brute
// force identical; cached maps; penumbra width of sphere and tube lights.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>

#include "candela/content/png_writer.h"
#include "passes/shadows/cascades.h"
#include "passes/shadows/shadows_bindings.h"
#include "shadow_reference.h"
#include "test_scene.h"

using namespace candela::render;
using namespace candela::render::test;
using candela::content::LightType;

namespace {

constexpr uint32_t kSize = 128;
constexpr uint32_t kCascadeSize = 1024;
constexpr float kShadowDistance = 15.0f;
constexpr uint32_t kLocalTile = 256;  // the tests' lights fill the view: their largest tile

RendererOptions shadowOptions(LightCulling culling = LightCulling::Clustered) {
    RendererOptions o;
    o.lightCulling = culling;
    o.shadowCascadeSize = kCascadeSize;
    o.shadowDistance = kShadowDistance;
    o.shadowMaxTileSize = kLocalTile;
    return o;
}

// A white Lambert floor and one box, seen from above.
TestScene floorWithBox(const Box& box) {
    TestScene scene;
    scene.width = scene.height = kSize;
    scene.add(candela::content::makePlane(8.0f, 4), lambertWhite());
    const glm::vec3 half = 0.5f * (box.hi - box.lo);
    scene.add(candela::content::makeBox({half.x, half.y, half.z}), lambertWhite(),
              glm::translate(glm::mat4(1.0f), 0.5f * (box.lo + box.hi)));
    scene.lookAt({0.0f, 5.0f, 3.5f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
    return scene;
}

// The light's ray from a floor point, and the size of a shadow texel there (metres on the
// floor, stretched by the light's slant).
struct LightProbe {
    glm::vec3 towardLight;  // end of the shadow ray
    float texel;
};

// Texel size on the floor at p for each kind of light, as the shadow pass plans the maps.
LightProbe probe(const LightInstance& l, const TestScene& scene, const glm::vec3& p) {
    if (l.light.type == LightType::Directional) {
        const glm::vec3 toLight = -glm::normalize(l.direction);
        const std::vector<float> s =
            practicalSplits(scene.camera.nearPlane, kShadowDistance, 4, kPracticalSplitLambda);
        float texel = 1.0f;
        for (uint32_t i = 0; i < 4; ++i) {
            const CascadeView c =
                fitCascade(scene.camera, s[i], s[i + 1], l.direction, kCascadeSize, -10.0f);
            if (glm::length(p - glm::vec3(c.sphere)) < c.sphere.w) {
                texel = c.texelWorld;
                break;
            }
        }
        return {p + toLight * 100.0f, texel / std::max(toLight.y, 0.2f)};
    }
    const glm::vec3 d = l.position - p;
    const glm::vec3 a = glm::abs(d);
    const float depth = std::max({a.x, a.y, a.z});  // along the cube face's (or spot's) axis
    // Spots wider than SHADOW_MAX_SPOT_HALF_ANGLE are mapped by cube faces.
    const bool singleView = l.light.type == LightType::Spot &&
                            l.light.outerConeAngle <= float(SHADOW_MAX_SPOT_HALF_ANGLE);
    const float tanHalf = singleView ? std::tan(l.light.outerConeAngle) * (1.0f + 4.0f / kLocalTile)
                                     : 1.0f + 4.0f / kLocalTile;
    const float slant = std::max(glm::normalize(d).y, 0.2f);
    return {l.position, 2.0f * tanHalf / kLocalTile * depth / slant};
}

struct MaskResult {
    int shadowed = 0, lit = 0;  // truly, outside the edge band
    int shadowedRenderedLit = 0, litRenderedShadowed = 0;
};

// Renders the scene with the light casting and not, and compares which floor pixels are in
// shadow (rendered at under half the unshadowed radiance) with a ray cast toward the light,
// leaving out pixels within two shadow texels of a shadow edge. `near` limits the compared
// pixels to those within that distance of the box's footprint (0: all).
MaskResult compareWithRayCast(TestScene scene, const Box& box, const LightInstance& light,
                              float near = 0.0f) {
    GpuContext context(requiredValidation());
    LightInstance on = light;
    on.light.castShadows = true;
    LightInstance off = light;
    off.light.castShadows = false;
    scene.lights = {off};
    const CapturedFrame plain = scene.render(context, shadowOptions());
    scene.lights = {on};
    RendererStats stats;
    const CapturedFrame shadowed = scene.render(context, shadowOptions(), &stats);
    EXPECT_EQ(stats.shadowedLights, 1u);
    EXPECT_EQ(stats.shadowMapsRendered, 1u);

    float brightest = 0.0f;
    for (size_t i = 1; i < plain.hdrRgb.size(); i += 3)
        brightest = std::max(brightest, plain.hdrRgb[i]);
    auto inShadow = [&](const glm::vec3& p, const glm::vec3& end) {
        return segmentHitsBox(p, end, box);
    };
    MaskResult r;
    std::vector<uint8_t> debug(kSize * kSize * 4, 0);
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            const std::optional<glm::vec3> hit = scene.pixelOnPlane(x, y);
            if (!hit) continue;
            const glm::vec3 p = *hit;
            if (segmentHitsBox(scene.camera.position, p, box)) continue;  // the box, not floor
            if (std::abs(p.x) > 7.5f || std::abs(p.z) > 7.5f) continue;
            const float unshadowed = hdrPixel(plain, x, y)[1];
            if (unshadowed < 1e-3f * brightest) continue;  // the light does not reach it
            if (near > 0.0f) {
                const glm::vec3 c = glm::clamp(p, box.lo, box.hi);
                if (glm::length(glm::vec2(p.x - c.x, p.z - c.z)) > near) continue;
            }
            const LightProbe pr = probe(light, scene, p);
            const bool truth = inShadow(p, pr.towardLight);
            bool edge = false;
            const float band = 2.0f * pr.texel;
            for (const glm::vec3 o : {glm::vec3(band, 0, 0), glm::vec3(-band, 0, 0),
                                      glm::vec3(0, 0, band), glm::vec3(0, 0, -band)}) {
                const glm::vec3 q = p + o;
                // Points under the box are in its shadow whatever the ray says.
                edge |= inShadow(q, probe(light, scene, q).towardLight) != truth;
            }
            const bool rendered = hdrPixel(shadowed, x, y)[1] < 0.5f * unshadowed;
            debug[(y * kSize + x) * 4 + 0] = truth ? 255 : 0;
            debug[(y * kSize + x) * 4 + 1] = rendered ? 255 : 0;
            debug[(y * kSize + x) * 4 + 2] = edge ? 128 : 0;
            debug[(y * kSize + x) * 4 + 3] = 255;
            if (edge) continue;
            if (truth) {
                ++r.shadowed;
                r.shadowedRenderedLit += rendered ? 0 : 1;
            } else {
                ++r.lit;
                r.litRenderedShadowed += rendered ? 1 : 0;
            }
        }
    }
    // CANDELA_SHADOW_DEBUG=DIR: the masks as images (red: ray cast in shadow, green: rendered
    // in shadow, blue: edge band), 4x enlarged, for looking at a failure.
    if (const char* dir = std::getenv("CANDELA_SHADOW_DEBUG")) {
        static int n = 0;
        std::vector<uint8_t> big(kSize * kSize * 64);
        for (uint32_t i = 0; i < kSize * 4; ++i)
            for (uint32_t j = 0; j < kSize * 4; ++j)
                for (int c = 0; c < 4; ++c)
                    big[(i * kSize * 4 + j) * 4 + c] = debug[((i / 4) * kSize + j / 4) * 4 + c];
        candela::content::writePng(std::string(dir) + "/mask" + std::to_string(n++) + ".png",
                                   kSize * 4, kSize * 4, 4, big.data());
    }
    return r;
}

void expectMatches(const MaskResult& r, int minimumShadowed) {
    EXPECT_GE(r.shadowed, minimumShadowed);
    EXPECT_GE(r.lit, 100);
    EXPECT_LT(double(r.shadowedRenderedLit), 0.01 * r.shadowed)
        << r.shadowedRenderedLit << " of " << r.shadowed << " shadowed pixels render lit";
    EXPECT_LT(double(r.litRenderedShadowed), 0.01 * r.lit)
        << r.litRenderedShadowed << " of " << r.lit << " lit pixels render shadowed";
}

const Box kFloatingBox{{-0.5f, 0.6f, -0.5f}, {0.5f, 1.2f, 0.5f}};

LightInstance sun(const glm::vec3& direction) {
    LightInstance l;
    l.light.type = LightType::Directional;
    l.light.lux = 10.0f;
    l.direction = glm::normalize(direction);
    return l;
}

LightInstance spot(const glm::vec3& position, const glm::vec3& direction) {
    LightInstance l = pointLight(position, 2000.0f, 20.0f);
    l.light.type = LightType::Spot;
    l.light.outerConeAngle = 0.9f;
    l.light.innerConeAngle = 0.7f;
    l.direction = glm::normalize(direction);
    return l;
}

// The stability tests' count: pixels not fully lit in both frames (green under 99 % of the
// first frame's brightest), and how many of them changed by more than 1e-3 of it. The point
// pixel x shows after the camera moved was at pixel x + shift before.
struct ShadowedPixelChanges {
    int shadowed = 0;
    int changed = 0;
};

ShadowedPixelChanges countShadowedPixelChanges(const CapturedFrame& before,
                                               const CapturedFrame& after, uint32_t shift) {
    float brightest = 0.0f;
    for (size_t i = 1; i < before.hdrRgb.size(); i += 3)
        brightest = std::max(brightest, before.hdrRgb[i]);
    ShadowedPixelChanges count;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x + shift < kSize; ++x) {
            const float a = hdrPixel(before, x + shift, y)[1];
            const float b = hdrPixel(after, x, y)[1];
            if (std::min(a, b) > 0.99f * brightest) continue;  // fully lit in both
            ++count.shadowed;
            count.changed += std::abs(a - b) > 1e-3f * brightest ? 1 : 0;
        }
    }
    return count;
}

}  // namespace

TEST(ShadowMask, SunMatchesARayCast) {
    expectMatches(
        compareWithRayCast(floorWithBox(kFloatingBox), kFloatingBox, sun({0.5f, -1.0f, 0.3f})),
        200);
}

TEST(ShadowMask, SpotMatchesARayCast) {
    expectMatches(compareWithRayCast(floorWithBox(kFloatingBox), kFloatingBox,
                                     spot({0.6f, 2.6f, 0.3f}, {-0.2f, -1.0f, -0.1f})),
                  200);
}

// A spot wider than one perspective view can hold (83 degrees half-angle) shadows through
// cube faces: the box lies 79 degrees off the spot's axis and its shadow further out, which a
// single view (limited to about 74.5 degrees) never covered.
TEST(ShadowMask, WideSpotMatchesARayCast) {
    LightInstance wide = spot({3.0f, 1.5f, 0.3f}, {0.0f, -1.0f, 0.0f});
    wide.light.outerConeAngle = 1.45f;
    wide.light.innerConeAngle = 1.4f;
    expectMatches(compareWithRayCast(floorWithBox(kFloatingBox), kFloatingBox, wide), 200);
}

TEST(ShadowMask, PointMatchesARayCast) {
    expectMatches(compareWithRayCast(floorWithBox(kFloatingBox), kFloatingBox,
                                     pointLight({-0.7f, 2.4f, 0.4f}, 2000.0f, 20.0f)),
                  200);
}

// Peter-panning: the shadow of a box resting on the floor starts at its foot. Compared
// within 30 cm of the box, under a low sun and a point light.
TEST(ShadowBias, NoGapUnderABoxOnTheFloor) {
    const Box resting{{-0.5f, 0.0f, -0.5f}, {0.5f, 0.8f, 0.5f}};
    expectMatches(
        compareWithRayCast(floorWithBox(resting), resting, sun({1.0f, -0.7f, 0.4f}), 0.3f), 50);
    expectMatches(compareWithRayCast(floorWithBox(resting), resting,
                                     pointLight({-1.6f, 1.6f, 0.3f}, 2000.0f, 20.0f), 0.3f),
                  50);
}

// Acne: a plane tilted 60 degrees, lit by a sun and a spot with nothing in the way, renders
// exactly as without shadows (every pixel within 1%).
TEST(ShadowBias, NoAcneOnA60DegreeSlope) {
    TestScene scene;
    scene.width = scene.height = kSize;
    const glm::mat4 tilt = glm::rotate(glm::mat4(1.0f), glm::radians(60.0f), glm::vec3(0, 0, 1));
    scene.add(candela::content::makePlane(3.0f, 4), lambertWhite(), tilt);
    scene.lookAt({-5.0f, 3.0f, 5.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
    GpuContext context(requiredValidation());
    const glm::vec3 normal = glm::vec3(tilt * glm::vec4(0, 1, 0, 0));
    // From straight above (NoL 0.5) and grazing (NoL about 0.17).
    const glm::vec3 grazing = glm::normalize(-normal + 5.6f * glm::vec3(0, 0, 1));
    for (LightInstance light :
         {sun({0.0f, -1.0f, 0.0f}), sun(grazing),
          spot(normal * 3.0f + glm::vec3(0, 1.0f, 0), -normal - glm::vec3(0, 0.33f, 0))}) {
        light.light.castShadows = false;
        scene.lights = {light};
        const CapturedFrame plain = scene.render(context, shadowOptions());
        scene.lights[0].light.castShadows = true;
        const CapturedFrame shadowed = scene.render(context, shadowOptions());
        int lit = 0, darker = 0;
        for (size_t i = 1; i < plain.hdrRgb.size(); i += 3) {
            if (plain.hdrRgb[i] <= 1e-4f) continue;
            ++lit;
            darker += shadowed.hdrRgb[i] < 0.99f * plain.hdrRgb[i] ? 1 : 0;
        }
        EXPECT_GT(lit, 2000);
        EXPECT_EQ(darker, 0) << "pixels darkened by self-shadowing, of " << lit << " (light "
                             << light.direction.x << ", " << light.direction.y << ", "
                             << light.direction.z << ")";
    }
}

// A camera moved by a tenth of a cascade texel changes no shadowed pixel. It looks straight
// down and moves by exactly one pixel's footprint on the floor, so the pixel that sees a floor
// point after the move saw the same point, one pixel over, before it. A narrow view and small
// cascades make that footprint a tenth of a texel at a usable height.
TEST(ShadowStability, MovingTheCameraByATenthOfATexelChangesNoShadowedPixel) {
    constexpr uint32_t kSmallCascade = 256;
    const float fov = glm::radians(20.0f);
    TestScene scene;
    scene.width = scene.height = kSize;
    scene.add(candela::content::makePlane(8.0f, 4), lambertWhite());
    // A slab over x < 0 whose shadow edge crosses the view.
    const Box slab{{-2.0f, 0.3f, -2.0f}, {-0.07f, 0.4f, 2.0f}};
    scene.add(candela::content::makeBox({0.5f * (slab.hi.x - slab.lo.x), 0.05f, 2.0f}),
              lambertWhite(), glm::translate(glm::mat4(1.0f), 0.5f * (slab.lo + slab.hi)));
    scene.lights = {sun({0.2f, -1.0f, 0.1f})};
    scene.lights[0].light.castShadows = true;
    RendererOptions options = shadowOptions();
    options.shadowCascadeSize = kSmallCascade;
    // The first cascade's texel (its size does not depend on where the camera is).
    scene.lookAt({0.0f, 0.2f, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, fov);
    const std::vector<float> s =
        practicalSplits(scene.camera.nearPlane, kShadowDistance, 4, kPracticalSplitLambda);
    const CascadeView first =
        fitCascade(scene.camera, s[0], s[1], scene.lights[0].direction, kSmallCascade, -10.0f);
    const float footprint = 0.1f * first.texelWorld;
    const float height = footprint * float(kSize) / (2.0f * std::tan(0.5f * fov));
    ASSERT_GT(height, 2.0f * scene.camera.nearPlane);
    ASSERT_LT(height, 0.8f * s[1]);  // the floor below is well inside the first cascade
    scene.lookAt({0.0f, height, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, fov);
    GpuContext context(requiredValidation());
    const CapturedFrame before = scene.render(context, options);
    scene.lookAt({footprint, height, 0.0f}, {footprint, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, fov);
    const CapturedFrame after = scene.render(context, options);
    // Moved along +x: the point at pixel x now was at pixel x + 1 before.
    const auto [shadowed, changed] = countShadowedPixelChanges(before, after, 1);
    EXPECT_GT(shadowed, 2000);
    EXPECT_EQ(changed, 0) << "of " << shadowed << " shadowed pixels";
}

// A camera turned by a tenth of a degree changes no shadowed pixel. The camera looks down and
// forward (30 degrees from straight down) and pitches about the x axis, so the floor slides
// along z under the pixels and the first cascade's centre moves in y and z, a fraction of a
// texel along the grid's axes: unsnapped, the texel grid would move with it. A slab above the
// camera (out of view) casts an edge running along z, and one axis of the cascades' texel grid
// runs along z too (the sun has no z component), so the shadow on the floor depends on x alone
// and each pixel must keep its value (columns near the edge keep their floor x to a few
// micrometres).
TEST(ShadowStability, TurningTheCameraByATenthOfADegreeChangesNoShadowedPixel) {
    constexpr uint32_t kSmallCascade = 256;
    const float fov = glm::radians(20.0f);
    TestScene scene;
    scene.width = scene.height = kSize;
    scene.add(candela::content::makePlane(8.0f, 4), lambertWhite());
    // 1.0 to 1.1 m high, over x < -0.66: its top edge casts the shadow edge onto x = 0, under
    // the middle column, whose floor x the turn does not change.
    const Box slab{{-3.0f, 1.0f, -3.0f}, {-0.66f, 1.1f, 3.0f}};
    scene.add(candela::content::makeBox({0.5f * (slab.hi.x - slab.lo.x), 0.05f, 3.0f}),
              lambertWhite(), glm::translate(glm::mat4(1.0f), 0.5f * (slab.lo + slab.hi)));
    scene.lights = {sun({0.6f, -1.0f, 0.0f})};
    scene.lights[0].light.castShadows = true;
    RendererOptions options = shadowOptions();
    options.shadowCascadeSize = kSmallCascade;
    const glm::vec3 eye{0.0f, 0.3f, 0.17f};
    auto look = [&](float pitch) {
        const float down = glm::radians(30.0f) + pitch;  // from straight down, toward -z
        scene.lookAt(eye, eye + glm::vec3(0.0f, -std::cos(down), -std::sin(down)),
                     {0.0f, 1.0f, 0.0f}, fov);
    };
    const std::vector<float> s = practicalSplits(0.05f, kShadowDistance, 4, kPracticalSplitLambda);
    look(0.0f);
    const CascadeView straight =
        fitCascade(scene.camera, s[0], s[1], scene.lights[0].direction, kSmallCascade, -10.0f);
    GpuContext context(requiredValidation());
    const CapturedFrame before = scene.render(context, options);
    look(glm::radians(0.1f));
    const CascadeView turnedCascade =
        fitCascade(scene.camera, s[0], s[1], scene.lights[0].direction, kSmallCascade, -10.0f);
    // The turn moves the cascade's centre across the grid by a visible fraction of a texel.
    const glm::mat3 basis = lightBasis(scene.lights[0].direction);
    const float across =
        std::abs(glm::dot(glm::vec3(turnedCascade.sphere) - glm::vec3(straight.sphere), basis[1]));
    ASSERT_GT(across, 0.02f * straight.texelWorld);
    const CapturedFrame after = scene.render(context, options);
    const auto [shadowed, changed] = countShadowedPixelChanges(before, after, 0);
    EXPECT_GT(shadowed, 2000);
    EXPECT_EQ(changed, 0) << "of " << shadowed << " shadowed pixels; the turn moved the cascade "
                          << across / straight.texelWorld << " texels across its grid";
}

// Subsurface transmission takes its thickness from the shadow map (the depth of the shaded
// point behind the nearest blocker toward the light): two subsurface slabs, 2 cm and 8 cm
// thick, under a sun from straight above, seen from below. Their undersides face away from
// the sun and show only transmitted light, which must fall with the thickness as
// exp(-t / 0.05 m) (shadows.glsl kSubsurfaceMeanFreePath): the thick slab's over the thin
// one's is exp(-1.2) = 0.30. The camera sits midway, so both are seen at mirrored angles.
TEST(ShadowSubsurface, TransmissionFallsWithTheThicknessInTheShadowMap) {
    TestScene scene;
    scene.width = scene.height = kSize;
    candela::content::Material wax = lambertWhite();
    wax.shadingModel = candela::content::ShadingModel::Subsurface;
    wax.subsurfaceOpacity = 0.5f;
    for (const auto& [x, thickness] : {std::pair{-0.3f, 0.02f}, std::pair{0.3f, 0.08f}}) {
        scene.add(candela::content::makeBox({0.2f, 0.5f * thickness, 0.2f}), wax,
                  glm::translate(glm::mat4(1.0f), glm::vec3(x, 1.0f + 0.5f * thickness, 0.0f)));
    }
    scene.lookAt({0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, -1.0f});
    scene.lights = {sun({0.0f, -1.0f, 0.0f})};
    scene.lights[0].light.castShadows = true;
    GpuContext context(requiredValidation());
    const CapturedFrame frame = scene.render(context, shadowOptions());
    double sum[2] = {0.0, 0.0};
    int count[2] = {0, 0};
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            const std::optional<glm::vec3> p = scene.pixelOnPlane(x, y, 1.0f);
            if (!p || std::abs(p->z) > 0.15f) continue;
            // The middle of each underside, clear of its edges.
            const int slab = std::abs(p->x + 0.3f) < 0.15f   ? 0
                             : std::abs(p->x - 0.3f) < 0.15f ? 1
                                                             : -1;
            if (slab < 0) continue;
            sum[slab] += hdrPixel(frame, x, y)[1];
            ++count[slab];
        }
    }
    ASSERT_GT(count[0], 200);
    ASSERT_GT(count[1], 200);
    const double thin = sum[0] / count[0], thick = sum[1] / count[1];
    ASSERT_GT(thin, 0.0);
    std::printf("transmitted: 2 cm %.5f, 8 cm %.5f cd/m^2, ratio %.4f (exp(-1.2) = %.4f)\n", thin,
                thick, thick / thin, std::exp(-1.2));
    EXPECT_NEAR(thick / thin, std::exp(-1.2), 0.1 * std::exp(-1.2));
}

// With shadows, clustered lists give the brute-force image (within float summation order).
TEST(ShadowClustering, ClusteredMatchesBruteForce) {
    TestScene scene = floorWithBox(kFloatingBox);
    scene.lights = {sun({0.5f, -1.0f, 0.3f}), spot({0.6f, 2.6f, 0.3f}, {-0.2f, -1.0f, -0.1f}),
                    pointLight({-0.7f, 2.4f, 0.4f}, 2000.0f, 6.0f),
                    pointLight({2.0f, 1.0f, 1.0f}, 800.0f, 3.0f),
                    pointLight({-3.0f, 1.5f, -2.0f}, 800.0f, 4.0f)};
    scene.lights[3].light.sourceRadius = 0.2f;
    scene.lights[4].light.sourceLength = 1.0f;
    for (LightInstance& l : scene.lights)
        l.light.castShadows = true;
    GpuContext context(requiredValidation());
    RendererStats stats;
    const CapturedFrame clustered = scene.render(context, shadowOptions(), &stats);
    EXPECT_EQ(stats.shadowedLights, 5u);
    const CapturedFrame brute = scene.render(context, shadowOptions(LightCulling::BruteForce));
    double worst = 0.0;
    for (size_t i = 0; i < clustered.hdrRgb.size(); ++i) {
        const double a = clustered.hdrRgb[i], b = brute.hdrRgb[i];
        worst = std::max(worst, std::abs(a - b) / std::max(std::abs(b), 1e-3));
    }
    EXPECT_LT(worst, 1e-4);
}

// A second frame with nothing changed renders no map; the stats say so. Over the render
// budget, moved lights keep last frame's maps and take turns to render.
TEST(ShadowCache, UnchangedLightsKeepTheirMaps) {
    TestScene scene = floorWithBox(kFloatingBox);
    scene.lights = {pointLight({-0.7f, 2.4f, 0.4f}, 2000.0f, 6.0f),
                    spot({0.6f, 2.6f, 0.3f}, {-0.2f, -1.0f, -0.1f})};
    for (LightInstance& l : scene.lights)
        l.light.castShadows = true;
    GpuContext context(requiredValidation());
    RendererStats stats;
    const CapturedFrame once = scene.render(context, shadowOptions(), &stats, 1);
    EXPECT_EQ(stats.shadowMapsRendered, 2u);
    EXPECT_EQ(stats.shadowMapsCached, 0u);
    const CapturedFrame twice = scene.render(context, shadowOptions(), &stats, 2);
    EXPECT_EQ(stats.shadowMapsRendered, 0u);
    EXPECT_EQ(stats.shadowMapsCached, 2u);
    EXPECT_EQ(once.hdrRgb, twice.hdrRgb);

    // Over the per-frame render budget, a light that moved keeps last frame's maps: both lights
    // move by 1 mm with room for one map, so one renders, the other samples its old map with
    // its old views (shadowed nearly as before, never unshadowed), and the next frame renders it.
    RendererOptions budget = shadowOptions();
    budget.shadowRenderBudget = 1;
    SceneResources resources(context);
    resources.setEnvironment(scene.environment);
    FrameInputs inputs = scene.prepare(resources);
    Renderer renderer(context, kSize, kSize, budget);
    FrameSubmitter submitter(context);
    FrameReadback readback(context, kSize, kSize);
    std::vector<RendererStats> frames;
    for (int frame = 0; frame < 3; ++frame) {
        if (frame > 0) {
            for (LightInstance& l : scene.lights)  // inputs.scene.lights views these
                l.position.x += 0.001f;
        }
        VkCommandBuffer cmd = renderer.recordFrame(submitter, inputs, &resources);
        if (frame == 1) readback.recordCopy(cmd, renderer);
        submitter.submit();
        submitter.waitIdle();
        frames.push_back(renderer.collectStats());
    }
    EXPECT_EQ(frames[0].shadowMapsRendered, 2u);  // nothing to keep yet
    EXPECT_EQ(frames[1].shadowMapsRendered, 1u);
    EXPECT_EQ(frames[1].shadowMapsKept, 1u);
    EXPECT_EQ(frames[2].shadowMapsRendered, 1u);  // the one that waited goes first
    EXPECT_EQ(frames[2].shadowMapsKept, 1u);
    const CapturedFrame kept = readback.read();
    int differ = 0;
    for (size_t i = 1; i < kept.hdrRgb.size(); i += 3)
        differ += std::abs(kept.hdrRgb[i] - once.hdrRgb[i]) > 0.05f * once.hdrRgb[i] + 1e-3f;
    EXPECT_LT(differ, int(kSize * kSize / 100)) << "pixels changed by more than 5%";
}

namespace {

// The penumbra a light casts past the straight edge of a slab (x < 0, 0.49 to 0.51 m high)
// onto the floor, with the light 2 m over the edge: the 10%-90% width of the visibility ramp
// across the edge, divided by 0.8 (the share of a linear ramp between 10% and 90%), in metres.
float measuredPenumbra(const LightInstance& light) {
    TestScene scene;
    scene.width = scene.height = 192;
    scene.add(candela::content::makePlane(8.0f, 4), lambertWhite());
    scene.add(candela::content::makeBox({1.5f, 0.01f, 3.0f}), lambertWhite(),
              glm::translate(glm::mat4(1.0f), glm::vec3(-1.5f, 0.5f, 0.0f)));
    // Under the slab, looking down at the floor across the edge.
    scene.lookAt({0.8f, 0.45f, 0.0f}, {-0.2f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
    GpuContext context(requiredValidation());
    LightInstance l = light;
    l.light.castShadows = false;
    scene.lights = {l};
    const CapturedFrame plain = scene.render(context, shadowOptions());
    scene.lights[0].light.castShadows = true;
    const CapturedFrame shadowed = scene.render(context, shadowOptions());
    constexpr float kFrom = -0.5f, kBin = 0.005f;
    constexpr int kBins = 200;
    std::vector<double> sum(kBins, 0.0), count(kBins, 0.0);
    for (uint32_t y = 0; y < scene.height; ++y) {
        for (uint32_t x = 0; x < scene.width; ++x) {
            const std::optional<glm::vec3> p = scene.pixelOnPlane(x, y);
            if (!p || std::abs(p->z) > 0.3f) continue;
            const int bin = int(std::floor((p->x - kFrom) / kBin));
            const float unshadowed = hdrPixel(plain, x, y)[1];
            if (bin < 0 || bin >= kBins || unshadowed <= 0.0f) continue;
            sum[bin] += hdrPixel(shadowed, x, y)[1] / unshadowed;
            count[bin] += 1.0;
        }
    }
    // Where the binned visibility first rises past a level, interpolated between bins.
    auto crossing = [&](double level) {
        double previousX = 0.0, previousV = -1.0;
        for (int b = 0; b < kBins; ++b) {
            if (count[b] == 0.0) continue;
            const double v = sum[b] / count[b];
            const double x = kFrom + (b + 0.5) * kBin;
            if (v >= level && previousV >= 0.0 && previousV < level)
                return previousX + (x - previousX) * (level - previousV) / (v - previousV);
            previousX = x;
            previousV = v;
        }
        return std::nan("");
    };
    return float((crossing(0.9) - crossing(0.1)) / 0.8);
}

}  // namespace

// Penumbrae follow w = size * (d_receiver - d_blocker) / d_blocker within 20%: a sphere light
// of radius 0.2 m (size: its 0.4 m diameter) and a 1 m tube across the edge.
TEST(ShadowPenumbra, WidthMatchesTheGeometricPenumbra) {
    const float receiver = 2.0f, blocker = 2.0f - 0.51f;  // the slab's top faces the light
    LightInstance sphere = pointLight({0.0f, 2.0f, 0.0f}, 2000.0f, 10.0f);
    sphere.light.sourceRadius = 0.2f;
    LightInstance tube = pointLight({0.0f, 2.0f, 0.0f}, 2000.0f, 10.0f);
    tube.light.sourceLength = 1.0f;
    tube.tubeAxis = {1.0f, 0.0f, 0.0f};
    for (const auto& [light, size] : {std::pair{sphere, 0.4f}, std::pair{tube, 1.0f}}) {
        const float expected = size * (receiver - blocker) / blocker;
        const float measured = measuredPenumbra(light);
        std::printf("penumbra of a %.1f m light: measured %.3f m, geometric %.3f m\n", size,
                    measured, expected);
        EXPECT_NEAR(measured, expected, 0.2f * expected) << "light size " << size << " m";
    }
}
