#pragma once
// Packing shadow maps into one square depth atlas: every map is a power-of-two square tile,
// placed in Morton order largest first, which packs such squares without gaps. Over budget,
// the lowest-priority requests get smaller tiles (halved in turn, down to kMinShadowTile), so
// no light ever loses its shadow. CPU only, unit-tested without a device.
#include <cstdint>
#include <span>
#include <vector>

namespace candela::render {

inline constexpr uint32_t kMinShadowTile = 8;

struct ShadowTileRequest {
    uint32_t tiles = 1;      // maps of this request (6 for a cube, the cascade count, 1)
    uint32_t size = 256;     // wanted texels per side, a power of two >= kMinShadowTile
    float priority = 0.0f;   // lower shrinks first
    bool shrinkable = true;  // cascades keep their size
    uint32_t minSize = 16;   // a shrinkable request goes no lower
};

struct ShadowTile {
    uint32_t x = 0, y = 0, size = 0;
};

struct ShadowAtlasPlan {
    // Per request, its tiles (the request's `size` after shrinking).
    std::vector<std::vector<ShadowTile>> tiles;
    std::vector<uint32_t> sizes;
    uint64_t usedTexels = 0;
    bool fits = true;  // false: even the smallest sizes overflowed (tiles then left empty)
};

ShadowAtlasPlan planShadowAtlas(std::span<const ShadowTileRequest> requests, uint32_t atlasSize);

}  // namespace candela::render
