#include "clustered/light_assignment.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <functional>

#include "candela/ecs/job_system.h"
#include "clustered/light_bounds.h"
#include "clustered/light_frustum_prepass.h"
#include "clustered/quarter_box_test.h"
#include "lights/gpu_light_types.h"

namespace candela::render {

namespace {

constexpr float kSliceDepthMargin = 1e-3f;
constexpr float kPixelBoundsMargin = 1e-4f;  // relative to depth

using PairList = LightAssignment::PairList;

// Occupied clusters numbered tile by tile, slices ascending: tile t's clusters start at
// firstOfTile[t], and slice k is the popcount of the tile's mask below bit k after that.
struct OccupiedNumbering {
    std::span<const uint64_t> masks;
    std::vector<uint32_t> firstOfTile;  // tileCount + 1 entries

    uint32_t compact(uint32_t tile, uint32_t slice) const {
        return firstOfTile[tile] +
               uint32_t(std::popcount(masks[tile] & ((uint64_t(1) << slice) - 1)));
    }
};

// Per-call tables of what the walk would otherwise recompute per light and cell: the unit
// normals of every row and column plane and every slice's near depth. Built with the very
// expressions the walk used, so every test sees bit-identical values and the lists are
// unchanged.
struct WalkTables {
    std::vector<glm::vec3> rowTop, rowBottom;        // per row: planes y/d <= top, >= bottom
    std::vector<glm::vec3> columnLeft, columnRight;  // per column: x/d >= left, <= right
    std::vector<float> sliceDepth;                   // slices + 1 entries
    // Inner boundary j of each axis is about first + j * step: the guess tileRange starts from.
    float columnFirst = 0.0f, columnInvStep = 0.0f, rowFirst = 0.0f, rowInvStep = 0.0f;

    explicit WalkTables(const ClusterGrid& grid) {
        for (uint32_t y = 0; y < grid.tilesY; ++y) {
            rowTop.push_back(glm::normalize(glm::vec3(0.0f, -1.0f, -grid.rowTangent[y])));
            rowBottom.push_back(glm::normalize(glm::vec3(0.0f, 1.0f, grid.rowTangent[y + 1])));
        }
        for (uint32_t x = 0; x < grid.tilesX; ++x) {
            columnLeft.push_back(glm::normalize(glm::vec3(1.0f, 0.0f, grid.columnTangent[x])));
            columnRight.push_back(
                glm::normalize(glm::vec3(-1.0f, 0.0f, -grid.columnTangent[x + 1])));
        }
        for (uint32_t k = 0; k <= grid.slices; ++k)
            sliceDepth.push_back(grid.sliceDepth(k));
        columnFirst = grid.columnTangent[0];
        columnInvStep = 1.0f / (grid.columnTangent[1] - grid.columnTangent[0]);
        rowFirst = grid.rowTangent[0];
        rowInvStep = 1.0f / (grid.rowTangent[1] - grid.rowTangent[0]);
    }
};

// How many inner boundaries (boundaries[1 .. tiles-1]) satisfy `below`, a predicate true on a
// prefix of them. Starts at the guess from the uniform tile spacing and corrects it with exact
// comparisons, so the answer is the binary search's (NaN included) in one or two steps.
template <class Below>
uint32_t prefixCount(const std::vector<float>& boundaries, float guess, Below below) {
    const uint32_t tiles = uint32_t(boundaries.size() - 1);
    const float clamped = guess >= 0.0f ? std::min(guess, float(tiles - 1)) : 0.0f;  // NaN: 0
    uint32_t c = uint32_t(clamped);
    while (c > 0 && !below(boundaries[c]))
        --c;
    while (c + 1 < tiles && below(boundaries[c + 1]))
        ++c;
    return c;
}

// Index range [first, last] of the tiles whose boundaries interval [lo, hi] overlaps: tile i
// spans boundaries[i]..boundaries[i + 1], ascending (columns) or descending (rows).
void tileRange(const std::vector<float>& boundaries, float first0, float invStep, float lo,
               float hi, bool descending, uint32_t& first, uint32_t& last) {
    if (!descending) {
        first = prefixCount(boundaries, (lo - first0) * invStep, [&](float b) { return b < lo; });
        last = prefixCount(boundaries, (hi - first0) * invStep, [&](float b) { return b <= hi; });
    } else {
        first = prefixCount(boundaries, (hi - first0) * invStep, [&](float b) { return b > hi; });
        last = prefixCount(boundaries, (lo - first0) * invStep, [&](float b) { return b >= lo; });
    }
}

// The box [lo, hi] padded for the lighting shader's own (world-space) reconstruction of the
// points inside it.
bool lightTouchesPixelBox(const LightBounds& b, glm::vec3 lo, glm::vec3 hi) {
    const glm::vec3 pad(kPixelBoundsMargin * (1.0f - lo.z));
    return lightTouchesBox(b, lo - pad, hi + pad);
}

// The quarter bits of a list entry for a light and a cluster's quarter boxes (0: the light
// reaches none of its pixels). The exact test on the cluster's box (the quarters' union, stored
// densely beside them) first: most lights that reach the cell's planes miss it, and then the
// four quarter tests are skipped. The quarters test the light's bounding shape, which is the light
// for spheres and cones and the bounding sphere for capsules: assign_lights.comp does the same
// without the capsule's search loop (lavapipe's loop limit, see there), and the lists must be
// equal.
uint32_t quarterMask(const LightBounds& b, const float* clusterBox, const float* quarterBounds,
                     bool perQuarter) {
    if (!lightTouchesPixelBox(b, glm::vec3(clusterBox[0], clusterBox[1], clusterBox[2]),
                              glm::vec3(clusterBox[3], clusterBox[4], clusterBox[5]))) {
        return 0;
    }
    if (!perQuarter) return LIGHT_ENTRY_ALL_QUARTERS;
    return quarterBoxesTouched(b, quarterBounds, kPixelBoundsMargin) << LIGHT_ENTRY_QUARTER_SHIFT;
}

void assignOne(const ClusterGrid& grid, const WalkTables& tables, const LightBounds& b,
               uint32_t lightIndex, const ClusterOccupancy& occupancy,
               const OccupiedNumbering& numbering, bool quarterMasks, PairList& out) {
    const float centerDepth = -b.center.z;
    const float nearDepth = centerDepth - b.radius;
    const float farDepth = centerDepth + b.radius;
    if (farDepth < grid.nearPlane) return;  // wholly behind the near plane
    // Widened like the slice depths below, for the same rounding reason.
    const uint32_t firstSlice = grid.sliceOf(nearDepth * (1.0f - kSliceDepthMargin));
    const uint32_t lastSlice = grid.sliceOf(farDepth * (1.0f + kSliceDepthMargin));
    for (uint32_t k = firstSlice; k <= lastSlice; ++k) {
        // Widened by a relative margin: the shader's log-based slice of a pixel may round
        // across a boundary the CPU's exp-based depth puts a hair away.
        const float z0 = tables.sliceDepth[k] * (1.0f - kSliceDepthMargin);
        // The last slice holds everything past far.
        const float z1 = k + 1 == grid.slices
                             ? std::max(farDepth, tables.sliceDepth[k]) * 2.0f
                             : tables.sliceDepth[k + 1] * (1.0f + kSliceDepthMargin);
        // The sphere's widest cross-section inside this slice, and the depths it spans there.
        const float dz = std::clamp(centerDepth, z0, z1) - centerDepth;
        const float crossRadius = std::sqrt(std::max(b.radius * b.radius - dz * dz, 0.0f));
        const float depthLo = std::max(std::max(z0, nearDepth), 1e-6f);
        const float depthHi = std::min(z1, farDepth);
        if (depthHi < depthLo) continue;
        // x / d over the cross-section's extent, at both ends of the depth span.
        auto extent = [&](float c, float& lo, float& hi) {
            lo = std::min((c - crossRadius) / depthLo, (c - crossRadius) / depthHi);
            hi = std::max((c + crossRadius) / depthLo, (c + crossRadius) / depthHi);
        };
        float xLo, xHi, yLo, yHi;
        extent(b.center.x, xLo, xHi);
        extent(b.center.y, yLo, yHi);
        uint32_t x0, x1, y0, y1;
        if (xLo > grid.columnTangent.back() || xHi < grid.columnTangent.front()) continue;
        if (yLo > grid.rowTangent.front() || yHi < grid.rowTangent.back()) continue;
        tileRange(grid.columnTangent, tables.columnFirst, tables.columnInvStep, xLo, xHi, false, x0,
                  x1);
        tileRange(grid.rowTangent, tables.rowFirst, tables.rowInvStep, yLo, yHi, true, y0, y1);

        for (uint32_t y = y0; y <= y1; ++y) {
            const float top = grid.rowTangent[y], bottom = grid.rowTangent[y + 1];
            // Row planes through the camera: bottom <= y/d <= top.
            if (!lightReachesPositiveSide(b, tables.rowTop[y]) ||
                !lightReachesPositiveSide(b, tables.rowBottom[y])) {
                continue;
            }
            for (uint32_t x = x0; x <= x1; ++x) {
                const uint32_t tile = y * grid.tilesX + x;
                if (!(numbering.masks[tile] >> k & 1u)) continue;
                const float left = grid.columnTangent[x], right = grid.columnTangent[x + 1];
                if (!lightReachesPositiveSide(b, tables.columnLeft[x]) ||
                    !lightReachesPositiveSide(b, tables.columnRight[x])) {
                    continue;
                }
                const uint32_t cluster = grid.clusterIndex(x, y, k);
                uint32_t quarters = LIGHT_ENTRY_ALL_QUARTERS;
                if (!occupancy.pixelBounds.empty()) {
                    quarters = quarterMask(
                        b, &occupancy.pixelBounds[size_t(cluster) * CLUSTER_BOX_FLOATS],
                        &occupancy.pixelBounds[size_t(grid.clusterCount()) * CLUSTER_BOX_FLOATS +
                                               size_t(cluster) * CLUSTER_QUARTER_BOXES_FLOATS],
                        quarterMasks);
                    if (quarters == 0) continue;
                } else {
                    // The cell's view-space box (z is negative in front of the camera).
                    const glm::vec3 lo(std::min(left * z0, left * z1),
                                       std::min(bottom * z0, bottom * z1), -z1);
                    const glm::vec3 hi(std::max(right * z0, right * z1),
                                       std::max(top * z0, top * z1), -z0);
                    if (!lightTouchesBox(b, lo, hi)) continue;
                }
                out.cluster.push_back(numbering.compact(tile, k));
                out.light.push_back(lightIndex | quarters);
            }
        }
    }
}

}  // namespace

void assignLights(const ClusterGrid& grid, std::span<const LightInstance> lights,
                  const glm::mat4& view, const ClusterOccupancy& occupancy, ecs::JobSystem* jobs,
                  std::span<uint32_t> clusterRanges, LightAssignment& out) {
    out.lightIndices.clear();
    out.directionalCount = 0;
    for (uint32_t i = 0; i < lights.size(); ++i) {
        if (inEveryCluster(lights[i].light)) {
            out.lightIndices.push_back(i);
            ++out.directionalCount;
        }
    }

    // Without depth refinement every cluster counts as occupied.
    const uint32_t tileCount = grid.tileCount();
    std::vector<uint64_t> everySlice;
    OccupiedNumbering numbering;
    numbering.masks = occupancy.tileMasks;
    if (numbering.masks.empty()) {
        const uint64_t all = grid.slices >= 64 ? ~uint64_t(0) : (uint64_t(1) << grid.slices) - 1;
        everySlice.assign(tileCount, all);
        numbering.masks = everySlice;
    }
    numbering.firstOfTile.resize(size_t(tileCount) + 1);
    uint32_t occupied = 0;
    for (uint32_t t = 0; t < tileCount; ++t) {
        numbering.firstOfTile[t] = occupied;
        occupied += uint32_t(std::popcount(numbering.masks[t]));
    }
    numbering.firstOfTile[tileCount] = occupied;

    const WalkTables tables(grid);

    // Chunks of lights in order; each job fills its own pair list.
    constexpr size_t kLightsPerJob = 512;
    const size_t jobCount = (lights.size() + kLightsPerJob - 1) / kLightsPerJob;
    std::vector<PairList>& pairs = out.pairScratch;
    if (pairs.size() < jobCount) pairs.resize(jobCount);
    for (size_t job = 0; job < jobCount; ++job) {
        pairs[job].cluster.clear();
        pairs[job].light.clear();
    }
    auto work = [&](size_t begin, size_t end) {
        for (size_t job = begin; job < end; ++job) {
            PairList& list = pairs[job];
            const size_t first = job * kLightsPerJob;
            const size_t last = std::min(first + kLightsPerJob, lights.size());
            list.visible.clear();
            if (out.frustumPrepass) {
                lightsInFrustum(grid, lights, first, last, view, list.frustum, list.visible);
            } else {
                for (size_t i = first; i < last; ++i) {
                    if (inEveryCluster(lights[i].light)) continue;
                    list.visible.push_back(uint32_t(i));
                }
            }
            for (uint32_t i : list.visible) {
                assignOne(grid, tables, lightBoundsInView(lights[i], view), i, occupancy, numbering,
                          out.quarterMasks, list);
            }
        }
    };
    if (jobs) {
        jobs->parallelFor(jobCount, 1, work);
    } else {
        work(0, jobCount);
    }

    // Counting sort over the occupied clusters, visiting jobs in light order: lists stay
    // ascending.
    std::vector<uint32_t>& cursor = out.cursorScratch;
    cursor.assign(occupied, 0);
    size_t total = 0;
    for (size_t job = 0; job < jobCount; ++job) {
        const PairList& list = pairs[job];
        for (uint32_t c : list.cluster)
            ++cursor[c];
        total += list.cluster.size();
    }
    uint32_t offset = uint32_t(out.lightIndices.size());
    for (uint32_t c = 0; c < occupied; ++c) {
        const uint32_t count = cursor[c];
        cursor[c] = offset;
        offset += count;
    }
    // Ranges: reset what the last call wrote, then write every occupied cluster's.
    for (uint32_t cluster : out.rangedClusters) {
        clusterRanges[size_t(cluster) * 2] = 0;
        clusterRanges[size_t(cluster) * 2 + 1] = 0;
    }
    out.rangedClusters.clear();
    uint32_t c = 0;
    for (uint32_t t = 0; t < tileCount; ++t) {
        for (uint64_t bits = numbering.masks[t]; bits; bits &= bits - 1, ++c) {
            const uint32_t cluster = uint32_t(std::countr_zero(bits)) * tileCount + t;
            const uint32_t end = c + 1 < occupied ? cursor[c + 1] : offset;
            clusterRanges[size_t(cluster) * 2] = cursor[c];
            clusterRanges[size_t(cluster) * 2 + 1] = end - cursor[c];
            out.rangedClusters.push_back(cluster);
        }
    }
    out.lightIndices.resize(out.directionalCount + total);
    for (size_t job = 0; job < jobCount; ++job) {
        const PairList& list = pairs[job];
        for (size_t i = 0; i < list.cluster.size(); ++i) {
            out.lightIndices[cursor[list.cluster[i]]++] = list.light[i];
        }
    }
    out.assignedPairs = uint32_t(total);
    out.lightsInFrustum = 0;
    for (size_t job = 0; job < jobCount; ++job) {
        out.lightsInFrustum += uint32_t(pairs[job].visible.size());
    }
    out.occupiedClusters = occupied;
}

}  // namespace candela::render
