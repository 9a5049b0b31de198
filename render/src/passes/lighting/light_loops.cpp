#include "light_loops.h"

#include <array>

#include "candela/content/components/light.h"

namespace candela::render {

namespace {

constexpr std::array<LightLoop, 5> kLoops{kLightLoopPlain, kLightLoopUnshadowedPunctual,
                                          kLightLoopUnshadowed, kLightLoopPunctual, kLightLoopAny};

}  // namespace

bool lightLoopTakes(LightLoop loop, const content::Light& light, bool mapped) {
    const bool area =
        light.type == content::LightType::Rect || light.type == content::LightType::Disk;
    switch (loop) {
        case kLightLoopPlain:
            // The GPU light carries NaN and negative sizes as 0, which this reads the same way.
            return !mapped && content::isPlainPunctualLight(light);
        case kLightLoopUnshadowedPunctual:
            return !mapped && !area;
        case kLightLoopUnshadowed:
            return !mapped;
        case kLightLoopPunctual:
            return !area;
        case kLightLoopAny:
            return true;
    }
    return true;
}

uint32_t lightLoopsFor(std::span<const LightInstance> lights, std::span<const uint8_t> mapped,
                       bool clustered) {
    if (!clustered) return kLightLoopAny;
    uint32_t loops = 0;
    size_t walk = 0;  // the loop the walk of the whole buffer is in
    for (size_t i = 0; i < lights.size(); ++i) {
        const content::Light& light = lights[i].light;
        if (light.type == content::LightType::Directional) continue;
        const bool hasMap = i < mapped.size() && mapped[i] != 0;
        while (!lightLoopTakes(kLoops[walk], light, hasMap))
            ++walk;  // stops: the last loop takes any light
        loops |= kLoops[walk];
    }
    return loops;
}

}  // namespace candela::render
