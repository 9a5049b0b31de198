// The lighting shader's loops by light class (render/src/passes/lighting/light_loops.h): which
// loops a frame compiles in, and that no pixel's list can then lose a light, whatever the
// order of the light buffer and whichever lights reach the pixel.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "passes/lighting/light_loops.h"

using namespace candela::render;
using candela::content::LightType;

namespace {

enum class Kind { Plain, Sphere, Tube, Spot, Rect, Disk, Directional };

LightInstance lightOf(Kind kind, bool castShadows = false) {
    LightInstance l;
    l.light.castShadows = castShadows;
    switch (kind) {
        case Kind::Plain:
            break;
        case Kind::Sphere:
            l.light.sourceRadius = 0.1f;
            break;
        case Kind::Tube:
            l.light.sourceLength = 1.0f;
            break;
        case Kind::Spot:
            l.light.type = LightType::Spot;
            break;
        case Kind::Rect:
            l.light.type = LightType::Rect;
            break;
        case Kind::Disk:
            l.light.type = LightType::Disk;
            break;
        case Kind::Directional:
            l.light.type = LightType::Directional;
            break;
    }
    return l;
}

// lighting.comp's walk of one pixel's list (ascending light indices) with the loops `enabled`:
// each loop takes lights while it takes them; returns the lights no loop took.
size_t lightsLost(const std::vector<LightInstance>& lights, const std::vector<uint8_t>& mapped,
                  const std::vector<size_t>& list, uint32_t enabled) {
    size_t at = 0;
    for (const LightLoopName& named : kLightLoopNames) {
        const LightLoop loop = named.bit;
        if (!(enabled & loop)) continue;
        while (at < list.size() &&
               (lights[list[at]].light.type == LightType::Directional ||
                lightLoopTakes(loop, lights[list[at]].light, mapped[list[at]] != 0))) {
            ++at;
        }
    }
    size_t lost = 0;
    for (; at < list.size(); ++at)
        lost += lights[list[at]].light.type != LightType::Directional;
    return lost;
}

// lightLoopsFor over lights and their maps given inline.
uint32_t loopsOf(std::vector<LightInstance> lights, std::vector<uint8_t> mapped) {
    return lightLoopsFor(lights, mapped, true);
}

}  // namespace

// In the light table's order, each class has its loop and nothing falls to the last, which
// carries every shape's code and the shadow code.
TEST(LightLoops, TheLightTablesOrderNeedsNoCatchAllLoop) {
    const std::vector<LightInstance> lights = {lightOf(Kind::Directional, true),
                                               lightOf(Kind::Plain),
                                               lightOf(Kind::Spot),
                                               lightOf(Kind::Sphere),
                                               lightOf(Kind::Tube),
                                               lightOf(Kind::Rect),
                                               lightOf(Kind::Disk),
                                               lightOf(Kind::Sphere, true),
                                               lightOf(Kind::Plain, true)};
    const std::vector<uint8_t> mapped = {1, 0, 0, 0, 0, 0, 0, 1, 1};
    EXPECT_EQ(lightLoopsFor(lights, mapped, true), kLightLoopPlain | kLightLoopUnshadowedPunctual |
                                                       kLightLoopUnshadowed | kLightLoopPunctual);
    // Only plain points: one loop (the games' common case).
    const std::vector<LightInstance> plain(4, lightOf(Kind::Plain));
    EXPECT_EQ(lightLoopsFor(plain, std::vector<uint8_t>(4, 0), true), kLightLoopPlain);
    // A caster whose map did not fit the atlas is lit without one, by the loops before.
    EXPECT_EQ(loopsOf({lightOf(Kind::Plain), lightOf(Kind::Plain, true)}, {0, 0}), kLightLoopPlain);
    // A rect that casts: only the last loop has both its shape and the shadow code.
    EXPECT_EQ(loopsOf({lightOf(Kind::Rect, true)}, {1}), kLightLoopAny);
    // Brute force runs the last loop only.
    EXPECT_EQ(lightLoopsFor(lights, mapped, false), kLightLoopAny);
}

// Out of class order (lights handed to the renderer by code, not the light table), a later
// light of an earlier class falls to the loop the walk is in, or a later one that takes it.
TEST(LightLoops, OutOfOrderLightsKeepTheLoopsThatTakeThem) {
    EXPECT_EQ(loopsOf({lightOf(Kind::Sphere), lightOf(Kind::Plain)}, {0, 0}),
              kLightLoopUnshadowedPunctual);
    EXPECT_EQ(loopsOf({lightOf(Kind::Rect), lightOf(Kind::Sphere)}, {0, 0}), kLightLoopUnshadowed);
    EXPECT_EQ(loopsOf({lightOf(Kind::Sphere, true), lightOf(Kind::Rect)}, {1, 0}),
              kLightLoopPunctual | kLightLoopAny);
}

// Every pixel's list is an ascending subset of the buffer: for random buffers (any order, any
// mix, casters with and without maps), every subset's walk through the enabled loops takes
// every light.
TEST(LightLoops, NoSubsetOfTheBufferLosesALight) {
    std::mt19937 rng(41);
    std::uniform_int_distribution<int> kind(0, 6), coin(0, 1), length(1, 10);
    for (int trial = 0; trial < 1000; ++trial) {
        std::vector<LightInstance> lights;
        std::vector<uint8_t> mapped;
        const int count = length(rng);
        for (int i = 0; i < count; ++i) {
            const bool casts = coin(rng) != 0;
            lights.push_back(lightOf(Kind(kind(rng)), casts));
            mapped.push_back(casts && coin(rng) != 0 ? 1 : 0);  // a caster may lose its map
        }
        const uint32_t enabled = lightLoopsFor(lights, mapped, true);
        for (uint32_t subset = 1; subset < (1u << count); ++subset) {
            std::vector<size_t> list;
            for (int i = 0; i < count; ++i)
                if (subset & (1u << i)) list.push_back(size_t(i));
            ASSERT_EQ(lightsLost(lights, mapped, list, enabled), 0u)
                << "trial " << trial << ", subset " << subset;
        }
    }
}
