#pragma once
// The light benchmarks' floor scene without a GPU: a square floor (y = 0) seen through a
// reverse-Z camera, rasterised analytically per pixel centre into what the depth occupancy
// pass would give the CPU light assignment (slicing, per-tile slice masks, per-cluster pixel
// boxes). Lets the assignment be timed and compared on its own, on any machine.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <vector>

#include "candela/render/frame_scene.h"
#include "clustered/cluster_grid.h"
#include "clustered/light_assignment.h"

namespace candela::render::bench {

// As kEmptyQuarterBound and quarterOfPixel in common/clusters.glsl.
constexpr float kEmptyQuarterBound = 3.0e38f;
inline uint32_t quarterOf(uint32_t tileSize, uint32_t px, uint32_t py) {
    return (px % tileSize) * 2 / tileSize + 2 * ((py % tileSize) * 2 / tileSize);
}

struct AnalyticFloorView {
    glm::mat4 view{1.0f};
    ClusterGrid grid;
    std::vector<uint64_t> tileMasks;
    std::vector<float> pixelBounds;  // cluster boxes, then 4 quarter boxes per cluster
    uint32_t width = 0, height = 0;
    std::vector<glm::vec3> pixels;  // view-space point per pixel; z == 0: background

    ClusterOccupancy occupancy() const { return {tileMasks, pixelBounds}; }
};

// The camera of the light culling benchmark: 6 m up, looking down the floor, 60 degrees.
inline AnalyticFloorView analyticFloorView(uint32_t width, uint32_t height, float floorHalfExtent,
                                           uint32_t tileSize = 16, uint32_t slices = 64) {
    AnalyticFloorView f;
    const glm::vec3 eye(0.0f, 6.0f, 20.0f);
    f.view = glm::lookAt(eye, glm::vec3(0.0f, 0.0f, -20.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    const float nearPlane = 0.05f;
    const glm::mat4 projection =
        reverseZPerspective(glm::radians(60.0f), float(width) / float(height), nearPlane);
    const float sx = projection[0][0], sy = projection[1][1];
    f.grid = ClusterGrid::make(tileSize, slices, width, height, sx, sy, nearPlane, 200.0f);
    const glm::mat3 toWorld = glm::transpose(glm::mat3(f.view));
    // Per pixel: view-space point on the floor, or depth 0 for background.
    f.width = width;
    f.height = height;
    std::vector<glm::vec3>& points = f.pixels;
    points.assign(size_t(width) * height, glm::vec3(0.0f));
    float minDepth = INFINITY, maxDepth = 0.0f;
    for (uint32_t py = 0; py < height; ++py) {
        for (uint32_t px = 0; px < width; ++px) {
            const float ndcX = (float(px) + 0.5f) / float(width) * 2.0f - 1.0f;
            const float ndcY = (float(py) + 0.5f) / float(height) * 2.0f - 1.0f;
            const glm::vec3 ray(ndcX / sx, ndcY / sy, -1.0f);  // view space, at depth 1
            const glm::vec3 worldRay = toWorld * ray;
            if (worldRay.y >= 0.0f) continue;
            const float depth = -eye.y / worldRay.y;
            const glm::vec3 hit = eye + worldRay * depth;
            if (std::abs(hit.x) > floorHalfExtent || std::abs(hit.z) > floorHalfExtent) continue;
            points[size_t(py) * width + px] = ray * depth;
            minDepth = std::min(minDepth, depth);
            maxDepth = std::max(maxDepth, depth);
        }
    }
    // As depth_occupancy.comp derives the slicing from the measured range.
    const float sliceNear = std::max(minDepth, nearPlane);
    f.grid.setSlicing(sliceNear, std::log(std::max(maxDepth, sliceNear * 1.01f) / sliceNear) /
                                     float(f.grid.slices));
    f.tileMasks.assign(f.grid.tileCount(), 0);
    // Every box starts empty (min > max), as depth_occupancy.comp writes empty quarters.
    f.pixelBounds.resize(size_t(f.grid.clusterCount()) * CLUSTER_BOUNDS_FLOATS);
    float* quarterBoxes = &f.pixelBounds[size_t(f.grid.clusterCount()) * CLUSTER_BOX_FLOATS];
    for (size_t i = 0; i < f.pixelBounds.size(); ++i)
        f.pixelBounds[i] = i % 6 < 3 ? kEmptyQuarterBound : -kEmptyQuarterBound;
    for (uint32_t py = 0; py < height; ++py) {
        for (uint32_t px = 0; px < width; ++px) {
            const glm::vec3 p = points[size_t(py) * width + px];
            if (p.z == 0.0f) continue;
            const uint32_t tile = (py / tileSize) * f.grid.tilesX + px / tileSize;
            const uint32_t slice = f.grid.sliceOf(-p.z);
            f.tileMasks[tile] |= uint64_t(1) << slice;
            const size_t cluster = size_t(slice) * f.grid.tileCount() + tile;
            float* box = &f.pixelBounds[cluster * CLUSTER_BOX_FLOATS];
            float* quarter = &quarterBoxes[cluster * CLUSTER_QUARTER_BOXES_FLOATS +
                                           quarterOf(tileSize, px, py) * 6];
            for (int c = 0; c < 3; ++c) {
                quarter[c] = std::min(quarter[c], p[c]);
                quarter[3 + c] = std::max(quarter[3 + c], p[c]);
            }
            for (int c = 0; c < 3; ++c) {
                box[c] = std::min(box[c], p[c]);
                box[3 + c] = std::max(box[3 + c], p[c]);
            }
        }
    }
    return f;
}

// The light culling benchmark's lights: constant density over a floor that grows with the
// count, radii 1-3 m, 0.1-1 m above it (light_culling_bench.cpp, same seed and order).
inline std::vector<LightInstance> floorLights(size_t count) {
    const float extent = 4.0f * std::sqrt(float(count));
    std::mt19937 rng{uint32_t(count)};
    std::uniform_real_distribution<float> x(-extent, extent), z(-2.0f * extent, 18.0f);
    std::uniform_real_distribution<float> y(0.1f, 1.0f), radius(1.0f, 3.0f);
    std::vector<LightInstance> lights;
    for (size_t i = 0; i < count; ++i) {
        LightInstance l;
        l.light.type = content::LightType::Point;
        l.light.lumens = 500.0f;
        // One statement each, for a fixed draw order: radius first, as g++ evaluated the
        // benchmark's former pointLight({x, y, z}, lumens, radius) call, so the scenes (and
        // the README's figures) stay the same.
        l.light.attenuationRadius = radius(rng);
        l.position.x = x(rng);
        l.position.y = y(rng);
        l.position.z = z(rng);
        lights.push_back(l);
    }
    return lights;
}

// Issue 22's mixed-size case: a fixed patch of floor in front of the camera (not growing with
// the count), lights of random radius 1-3 m at 0.1-1.5 m, so per pixel both small and large
// spheres overlap and some lights barely reach the floor.
inline std::vector<LightInstance> mixedSizeLights(size_t count) {
    std::mt19937 rng{uint32_t(count) * 7919u + 1u};
    std::uniform_real_distribution<float> x(-40.0f, 40.0f), z(-80.0f, 15.0f);
    std::uniform_real_distribution<float> y(0.1f, 1.5f), radius(1.0f, 3.0f);
    std::vector<LightInstance> lights;
    for (size_t i = 0; i < count; ++i) {
        LightInstance l;
        l.light.type = content::LightType::Point;
        l.light.lumens = 500.0f;
        l.position.x = x(rng);
        l.position.y = y(rng);
        l.position.z = z(rng);
        l.light.attenuationRadius = radius(rng);
        lights.push_back(l);
    }
    return lights;
}
constexpr float kMixedSizeFloorHalfExtent = 100.0f;

inline float floorHalfExtent(size_t count) {
    return std::max(100.0f, 2.5f * 4.0f * std::sqrt(float(count)));
}

}  // namespace candela::render::bench
