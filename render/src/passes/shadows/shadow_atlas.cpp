#include "passes/shadows/shadow_atlas.h"

#include <algorithm>
#include <numeric>

namespace candela::render {

namespace {

// The x (even bits) or y (odd bits) of a Morton index.
uint32_t compactBits(uint64_t v) {
    v &= 0x5555555555555555ull;
    v = (v | (v >> 1)) & 0x3333333333333333ull;
    v = (v | (v >> 2)) & 0x0f0f0f0f0f0f0f0full;
    v = (v | (v >> 4)) & 0x00ff00ff00ff00ffull;
    v = (v | (v >> 8)) & 0x0000ffff0000ffffull;
    v = (v | (v >> 16)) & 0x00000000ffffffffull;
    return uint32_t(v);
}

uint64_t cellsOf(uint32_t size) {
    const uint64_t side = size / kMinShadowTile;
    return side * side;
}

uint64_t cellsNeeded(std::span<const ShadowTileRequest> requests,
                     const std::vector<uint32_t>& sizes) {
    uint64_t cells = 0;
    for (size_t i = 0; i < requests.size(); ++i)
        cells += cellsOf(sizes[i]) * requests[i].tiles;
    return cells;
}

}  // namespace

ShadowAtlasPlan planShadowAtlas(std::span<const ShadowTileRequest> requests, uint32_t atlasSize) {
    ShadowAtlasPlan plan;
    plan.sizes.resize(requests.size());
    for (size_t i = 0; i < requests.size(); ++i)
        plan.sizes[i] = std::clamp(requests[i].size, kMinShadowTile, atlasSize);
    const uint64_t capacity = cellsOf(atlasSize);

    // Over budget: halve the lowest-priority shrinkable requests one at a time, round after
    // round, until everything fits; the last rounds may go below minSize to kMinShadowTile.
    std::vector<size_t> byPriority(requests.size());
    std::iota(byPriority.begin(), byPriority.end(), size_t(0));
    std::stable_sort(byPriority.begin(), byPriority.end(), [&](size_t a, size_t b) {
        return requests[a].priority < requests[b].priority;
    });
    uint64_t needed = cellsNeeded(requests, plan.sizes);
    for (bool belowMinimum : {false, true}) {
        bool shrunk = true;
        while (needed > capacity && shrunk) {
            shrunk = false;
            for (size_t i : byPriority) {
                if (needed <= capacity) break;
                const ShadowTileRequest& r = requests[i];
                const uint32_t floor = belowMinimum ? kMinShadowTile : r.minSize;
                if (!r.shrinkable || plan.sizes[i] / 2 < floor) continue;
                needed -= (cellsOf(plan.sizes[i]) - cellsOf(plan.sizes[i] / 2)) * r.tiles;
                plan.sizes[i] /= 2;
                shrunk = true;
            }
        }
    }

    // Largest first (ties in request order): each tile's first cell is then a multiple of
    // its own cell count, which Morton order turns into an aligned square.
    std::vector<size_t> bySize(requests.size());
    std::iota(bySize.begin(), bySize.end(), size_t(0));
    std::stable_sort(bySize.begin(), bySize.end(),
                     [&](size_t a, size_t b) { return plan.sizes[a] > plan.sizes[b]; });
    plan.tiles.resize(requests.size());
    uint64_t cursor = 0;
    for (size_t i : bySize) {
        const uint64_t cells = cellsOf(plan.sizes[i]);
        for (uint32_t t = 0; t < requests[i].tiles; ++t) {
            if (cursor + cells > capacity) {
                plan.fits = false;
                break;
            }
            plan.tiles[i].push_back({compactBits(cursor) * kMinShadowTile,
                                     compactBits(cursor >> 1) * kMinShadowTile, plan.sizes[i]});
            cursor += cells;
        }
    }
    plan.usedTexels = cursor * kMinShadowTile * kMinShadowTile;
    return plan;
}

}  // namespace candela::render
