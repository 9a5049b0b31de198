#include "light_loops.h"

#include "candela/content/components/light.h"
#include "candela/content/light_types.h"

namespace candela::render {

bool lightLoopTakes(LightLoop loop, const content::Light& light, bool mapped) {
    const bool area = content::isAreaLight(light.type);
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
        while (!lightLoopTakes(kLightLoopNames[walk].bit, light, hasMap))
            ++walk;  // stops: the last loop takes any light
        loops |= kLightLoopNames[walk].bit;
    }
    return loops;
}

}  // namespace candela::render
