#pragma once
// Which of lighting.comp's local-light loops a frame needs. llvmpipe runs every branch of a loop
// body for every light, and a loop's body at least once per pixel even when no lane enters it
// (render/README.md "What a shader costs on lavapipe"), so the lighting shader walks a pixel's
// list in runs, one loop per class with only that class's code, and a loop the frame's lights
// never reach is compiled out. Vulkan-free.
#include <cstdint>
#include <span>

#include "candela/render/frame_scene.h"
#include "light_loop_bits.h"

namespace candela::render {

// One bit per loop, in the order lighting.comp runs them; each takes the lights its class
// admits, until the first it does not (light_loop_bits.h says which).
enum LightLoop : uint32_t {
    kLightLoopPlain = LIGHT_LOOP_PLAIN,
    kLightLoopUnshadowedPunctual = LIGHT_LOOP_UNSHADOWED_PUNCTUAL,
    kLightLoopUnshadowed = LIGHT_LOOP_UNSHADOWED,
    kLightLoopPunctual = LIGHT_LOOP_PUNCTUAL,
    kLightLoopAny = LIGHT_LOOP_ANY,
};
inline constexpr uint32_t kAllLightLoops = LIGHT_LOOPS_ALL;

// The loops in the order lighting.comp runs them, each with its name in --stats `features`
// ("light_loop_" + name).
struct LightLoopName {
    LightLoop bit;
    const char* name;
};
inline constexpr LightLoopName kLightLoopNames[] = {
    {kLightLoopPlain, "plain"},
    {kLightLoopUnshadowedPunctual, "unshadowed_punctual"},
    {kLightLoopUnshadowed, "unshadowed"},
    {kLightLoopPunctual, "punctual"},
    {kLightLoopAny, "any"},
};

// Whether `loop` takes a light (lighting.comp's loopTakes, the same rules on the GPU light):
// `mapped`, it has a shadow map this frame.
bool lightLoopTakes(LightLoop loop, const content::Light& light, bool mapped);

// The loops a frame's lists need: those the walk of the whole light buffer (the slots) gives a
// light. Every cluster list is an ascending subsequence of the buffer, and the walk of a
// subsequence is never in a later loop at a light than the buffer's walk, which takes it, so
// each pixel's walk through these loops takes every light (a loop left out passes its lights on
// to a later one). `mapped[i]`: light i has a map (ShadowPass::lightsWithMaps). Directional
// lights have their own loop and are skipped; brute force (not clustered) runs the last loop.
uint32_t lightLoopsFor(std::span<const LightInstance> lights, std::span<const uint8_t> mapped,
                       bool clustered);

}  // namespace candela::render
