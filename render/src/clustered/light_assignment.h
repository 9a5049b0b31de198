#pragma once
// CPU light-to-cluster assignment, light-centric: each light visits only the clusters inside
// its bounds (slice range, then per-slice tile range from the sphere's cross-section), tests
// each against its bounds and the plane/box of the cell, and skips cells with no geometry.
// Lists keep lights in ascending index order, so the shader sums exactly as brute force does.
// Per-cluster work touches only occupied clusters: pairs are sorted over a compact numbering
// of them (tile-major, from the occupancy masks), and only their ranges are written.
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "candela/render/frame_scene.h"
#include "clustered/cluster_grid.h"
#include "clustered/light_frustum_prepass.h"
#include "common/light_list_entry.h"

namespace candela::ecs {
class JobSystem;
}

namespace candela::render {

struct LightAssignment {
    // Directional lights first (they reach every pixel, plain indices), then every cluster's
    // list of entries: light index | quarter mask (common/light_list_entry.h).
    std::vector<uint32_t> lightIndices;
    // Clusters whose range the last call wrote (the occupied ones); the next call resets
    // those it does not write again. Clear it when handing assignLights zeroed ranges.
    std::vector<uint32_t> rangedClusters;
    uint32_t directionalCount = 0;
    uint32_t occupiedClusters = 0;  // clusters holding geometry (all, without occupancy)
    uint32_t assignedPairs = 0;     // light-cluster pairs in the lists
    uint32_t lightsInFrustum = 0;   // local lights the frustum pre-pass passed to the walk

    // The SIMD frustum pre-pass (light_frustum_prepass.h). It changes no list; off only to
    // measure what it saves and to test that it changes nothing.
    bool frustumPrepass = true;
    // Per-quarter tests (ClusterOccupancy::pixelBounds). Off, every entry gets all four quarter
    // bits after the test on the cluster's box: the lists as before the masks, only to measure
    // what the masks cost and save.
    bool quarterMasks = true;

    // Scratch kept between calls, so a warm frame allocates (and page-faults) nothing: per job,
    // the light-cluster pairs it found in ascending light order; per occupied cluster, the
    // counting sort's cursor.
    struct PairList {
        std::vector<uint32_t> cluster;  // compact occupied-cluster number
        std::vector<uint32_t> light;
        std::vector<uint32_t> visible;  // the job's lights that passed the pre-pass
        LightFrustumScratch frustum;
    };
    std::vector<PairList> pairScratch;
    std::vector<uint32_t> cursorScratch;
};

// What the depth buffer says about each cluster; empty spans mean "assume every cluster is
// full of geometry" (no depth refinement).
struct ClusterOccupancy {
    // One 64-bit mask per tile: bit k set when the tile has a pixel in slice k.
    std::span<const uint64_t> tileMasks;
    // Per cluster, CLUSTER_BOX_FLOATS: view-space min xyz and max xyz of its pixels; then per
    // cluster, CLUSTER_QUARTER_BOXES_FLOATS: the same per quarter of its tile (quarterOfPixel
    // in clusters.glsl), min > max for a quarter without any (occupied clusters only;
    // common/light_list_entry.h). Entries get the bits of the quarters whose box the light
    // touches; without bounds every entry has all four.
    std::span<const float> pixelBounds;
};

// clusterRanges: per cluster, offset into lightIndices and count (2 uints per cluster; the
// lighting shader reads it). It must hold what the previous call with the same `out` left
// there, or zeros; clusters without geometry keep a zero range.
void assignLights(const ClusterGrid& grid, std::span<const LightInstance> lights,
                  const glm::mat4& view, const ClusterOccupancy& occupancy, ecs::JobSystem* jobs,
                  std::span<uint32_t> clusterRanges, LightAssignment& out);

}  // namespace candela::render
