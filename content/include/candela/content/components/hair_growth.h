#pragma once
// Hair grown on an entity's mesh (issue 19, Martin et al. 2014, GPU Pro 5, "TressFX: Advanced
// Real-Time Hair Rendering"): `count` strands `length` metres long, rooted at random points of the
// mesh's surface (from `seed`: the same seed, the same fur), in `style` (the glTF extras.hair
// keys). Scene files: an entity's "hair" block, beside its "mesh" (content/README.md). The strands
// themselves are generated where the frame is extracted (content::generateHair), not stored.
#include <cstdint>

#include "candela/content/material.h"

namespace candela::content {

struct HairGrowth {
    std::uint32_t count = 1000;
    float length = 0.05f;  // metres
    std::uint32_t seed = 1;
    HairStyle style;

    bool operator==(const HairGrowth&) const = default;
};

}  // namespace candela::content
