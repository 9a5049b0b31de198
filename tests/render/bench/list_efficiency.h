#pragma once
// Culling efficiency of CPU light lists on an analytic floor (analytic_floor.h), with the two
// bounds that say what tighter light/cluster tests could still gain: evaluated / lit
// light-pixel pairs for
//  - the lists assignLights built, entries skipped by pixels outside their quarter mask (what
//    the lighting pass evaluates),
//  - the same lists without the masks (every entry evaluated by the whole cluster, as before
//    the masks),
//  - exact per-cluster lists: a light listed only where it reaches at least one of the
//    cluster's pixels. No per-cluster bound (box, sphere, depth bitmask) can do better at
//    this grid,
//  - per-quarter boxes: each list entry of a 16 px cluster carries a 4-bit mask of the 8 x 8 px
//    quarters whose pixel box (view-space AABB, padded as the assignment pads) the light
//    touches, and a pixel skips entries whose bit for its quarter is clear,
//  - exact per-sub-tile lists: the exact test per quarter, the bound for such masks.
// Point lights only (a pixel is lit when it lies strictly inside the attenuation radius, where
// eq. 9's window is non-zero; the floor's lights all sit above it, so it faces them).
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <span>
#include <vector>

#include "analytic_floor.h"
#include "clustered/light_bounds.h"

namespace candela::render::bench {

struct ListEfficiency {
    uint64_t litPairs = 0;
    uint64_t maskedLitPairs = 0;  // lit pairs whose entry has the pixel's quarter bit
    double lists = 0.0;
    double listsUnmasked = 0.0;
    double exactPerCluster = 0.0;
    double quarterBoxes = 0.0;
    double quarterPlanes = 0.0;
    double exactPerSubTile = 0.0;
};

inline ListEfficiency listEfficiency(const AnalyticFloorView& f,
                                     std::span<const LightInstance> lights,
                                     const LightAssignment& assignment,
                                     std::span<const uint32_t> ranges) {
    const ClusterGrid& g = f.grid;
    std::vector<glm::vec4> light(lights.size());  // view-space centre, radius
    for (size_t i = 0; i < lights.size(); ++i) {
        light[i] = glm::vec4(glm::vec3(f.view * glm::vec4(lights[i].position, 1.0f)),
                             lights[i].light.attenuationRadius);
    }
    auto lit = [&](const glm::vec3& p, uint32_t i) {
        const glm::vec3 d = p - glm::vec3(light[i]);
        return glm::dot(d, d) < light[i].w * light[i].w;
    };
    // Pixels grouped by cluster, each tagged with its 8 px quarter of the tile.
    struct Pixel {
        uint32_t cluster;
        uint32_t quarter;
        uint32_t index;
    };
    std::vector<Pixel> pixels;
    for (uint32_t py = 0; py < f.height; ++py) {
        for (uint32_t px = 0; px < f.width; ++px) {
            const glm::vec3& p = f.pixels[size_t(py) * f.width + px];
            if (p.z == 0.0f) continue;
            const uint32_t tile = (py / g.tileSize) * g.tilesX + px / g.tileSize;
            pixels.push_back({g.sliceOf(-p.z) * g.tileCount() + tile, quarterOf(g.tileSize, px, py),
                              py * f.width + px});
        }
    }
    std::sort(pixels.begin(), pixels.end(), [](const Pixel& a, const Pixel& b) {
        return a.cluster != b.cluster ? a.cluster < b.cluster : a.quarter < b.quarter;
    });
    uint64_t maskedLit = 0;
    uint64_t evaluated = 0, unmasked = 0, exactCluster = 0, exactQuarter = 0, quarterBoxes = 0,
             litPairs = 0;
    uint64_t quarterPlanes = 0;
    const float columnStep = (g.columnTangent[1] - g.columnTangent[0]) / float(g.tileSize);
    const float rowStep = (g.rowTangent[1] - g.rowTangent[0]) / float(g.tileSize);
    std::vector<LightBounds> bounds;
    for (const LightInstance& l : lights)
        bounds.push_back(lightBoundsInView(l, f.view));
    for (size_t begin = 0; begin < pixels.size();) {
        size_t end = begin;
        while (end < pixels.size() && pixels[end].cluster == pixels[begin].cluster)
            ++end;
        const uint32_t offset = ranges[size_t(pixels[begin].cluster) * 2];
        const uint32_t count = ranges[size_t(pixels[begin].cluster) * 2 + 1];
        unmasked += uint64_t(count) * (end - begin);
        for (uint32_t k = 0; k < count; ++k) {
            const uint32_t entry = assignment.lightIndices[offset + k];
            const uint32_t i = entry & LIGHT_ENTRY_INDEX_MASK;
            for (size_t p = begin; p < end; ++p) {
                evaluated += entry >> (LIGHT_ENTRY_QUARTER_SHIFT + pixels[p].quarter) & 1u;
            }
            bool inCluster = false;
            for (size_t q = begin; q < end;) {
                size_t qEnd = q;
                while (qEnd < end && pixels[qEnd].quarter == pixels[q].quarter)
                    ++qEnd;
                bool inQuarter = false;
                glm::vec3 lo(INFINITY), hi(-INFINITY);
                for (size_t p = q; p < qEnd; ++p) {
                    lo = glm::min(lo, f.pixels[pixels[p].index]);
                    hi = glm::max(hi, f.pixels[pixels[p].index]);
                }
                const glm::vec3 pad(1e-4f * (1.0f - lo.z));  // as light_assignment.cpp
                if (lightTouchesBox(bounds[i], lo - pad, hi + pad)) quarterBoxes += qEnd - q;
                {
                    // The cluster's (not the quarter's) box, and the quarter's four planes.
                    const uint32_t cluster = pixels[q].cluster, tile = cluster % g.tileCount();
                    const uint32_t tx = tile % g.tilesX, ty = tile / g.tilesX;
                    const uint32_t quarter = pixels[q].quarter;
                    const float* box = &f.pixelBounds[size_t(cluster) * CLUSTER_BOX_FLOATS];
                    glm::vec3 blo(box[0], box[1], box[2]), bhi(box[3], box[4], box[5]);
                    const glm::vec3 bpad(1e-4f * (1.0f - blo.z));
                    const float half = float(g.tileSize / 2);
                    const float left =
                        quarter % 2 ? g.columnTangent[tx] + half * columnStep : g.columnTangent[tx];
                    const float right = quarter % 2 ? g.columnTangent[tx + 1]
                                                    : g.columnTangent[tx] + half * columnStep;
                    const float top =
                        quarter / 2 ? g.rowTangent[ty] + half * rowStep : g.rowTangent[ty];
                    const float bottom =
                        quarter / 2 ? g.rowTangent[ty + 1] : g.rowTangent[ty] + half * rowStep;
                    const LightBounds& b = bounds[i];
                    if (lightTouchesBox(b, blo - bpad, bhi + bpad) &&
                        lightReachesPositiveSide(b, glm::normalize(glm::vec3(1, 0, left))) &&
                        lightReachesPositiveSide(b, glm::normalize(glm::vec3(-1, 0, -right))) &&
                        lightReachesPositiveSide(b, glm::normalize(glm::vec3(0, -1, -top))) &&
                        lightReachesPositiveSide(b, glm::normalize(glm::vec3(0, 1, bottom)))) {
                        quarterPlanes += qEnd - q;
                    }
                }
                for (size_t p = q; p < qEnd; ++p) {
                    if (lit(f.pixels[pixels[p].index], i)) {
                        inQuarter = true;
                        ++litPairs;
                        maskedLit += entry >> (LIGHT_ENTRY_QUARTER_SHIFT + pixels[p].quarter) & 1u;
                    }
                }
                if (inQuarter) exactQuarter += qEnd - q;
                inCluster = inCluster || inQuarter;
                q = qEnd;
            }
            if (inCluster) exactCluster += end - begin;
        }
        begin = end;
    }
    ListEfficiency e;
    e.litPairs = litPairs;
    e.maskedLitPairs = maskedLit;
    const double lit1 = double(std::max<uint64_t>(litPairs, 1));
    e.lists = double(evaluated) / lit1;
    e.listsUnmasked = double(unmasked) / lit1;
    e.exactPerCluster = double(exactCluster) / lit1;
    e.quarterBoxes = double(quarterBoxes) / lit1;
    e.quarterPlanes = double(quarterPlanes) / lit1;
    e.exactPerSubTile = double(exactQuarter) / lit1;
    return e;
}

}  // namespace candela::render::bench
