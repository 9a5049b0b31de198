#include "passes/volumetrics/light_bins.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/vec4.hpp>

#include "candela/content/components/light.h"
#include "lights/gpu_light_types.h"

namespace candela::render {

namespace {

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The element (pixel or froxel column) whose centre is nearest NDC `ndc` on one axis, as a
// real number: ndc = (element * stride + offset) / extent * 2 - 1, inverted.
float elementAt(float ndc, float stride, float offset, float extent) {
    return ((ndc + 1.0f) * 0.5f * extent - offset) / stride;
}

// Bins [first, last] on one axis covered by elements [lo, hi] (reals, widened by one element
// each way for rounding); false when none of the axis' elements is in it.
bool binRange(float lo, float hi, uint32_t elements, uint32_t perBin, uint32_t& first,
              uint32_t& last) {
    const float top = float(elements - 1);
    lo = std::floor(lo) - 1.0f;
    hi = std::ceil(hi) + 1.0f;
    if (!(hi >= 0.0f) || !(lo <= top)) return false;
    first = uint32_t(std::clamp(lo, 0.0f, top)) / perBin;
    last = uint32_t(std::clamp(hi, 0.0f, top)) / perBin;
    return true;
}

}  // namespace

LightBinLayout volumeTileLayout(uint32_t width, uint32_t height) {
    LightBinLayout layout;
    layout.elements = {(width + 1) / 2, (height + 1) / 2, 1u};
    layout.perBin = {8u, 8u, 1u};
    layout.bins = {(layout.elements.x + 7) / 8, (layout.elements.y + 7) / 8, 1u};
    // Half-resolution pixel q marches the ray of full pixel 2q (volumetrics_volumes_march.comp).
    layout.stride = glm::vec2(2.0f);
    layout.offset = glm::vec2(0.5f);
    layout.extent = glm::vec2(float(width), float(height));
    return layout;
}

LightBinLayout froxelClusterLayout(const glm::uvec3& grid, float nearDepth, float farDepth) {
    LightBinLayout layout;
    layout.elements = grid;
    layout.perBin = {4u, 4u, 4u};
    layout.bins = (grid + 3u) / 4u;
    layout.stride = glm::vec2(1.0f);
    layout.offset = glm::vec2(0.5f);
    layout.extent = glm::vec2(float(grid.x), float(grid.y));
    layout.nearDepth = nearDepth;
    layout.farDepth = farDepth;
    layout.sliced = true;
    return layout;
}

LightVolumeBox lightVolumeBox(const LightInstance& instance) {
    const content::Light& light = instance.light;
    LightVolumeBox box;
    const float range =
        std::isfinite(light.attenuationRadius) ? std::max(light.attenuationRadius, 0.0f) : 0.0f;
    if (inEveryCluster(light) || !finite(instance.position)) {
        box.everywhere = true;
        return box;
    }
    // The range sphere bounds every local light: lightInScatteringUnshadowed windows point,
    // spot, sphere, tube, rect and disk lights alike by the distance to the light's position.
    box.min = instance.position - glm::vec3(range);
    box.max = instance.position + glm::vec3(range);
    if (light.type != content::LightType::Spot) return box;
    // A spot's volume (the range sphere cut by the cone) lies inside the cone cut at `range`
    // along its axis, whose box is that of the apex and the base disc; the volume is in both
    // boxes, so in their intersection.
    const float outer = std::clamp(light.outerConeAngle, 0.0f, 1.5707963f);
    if (!(outer < 1.4f)) return box;  // near 90 degrees the cone's box is the larger
    const glm::vec3 axis = glm::normalize(instance.direction);
    if (!finite(axis)) return box;
    const glm::vec3 base = instance.position + axis * range;
    const float discRadius = range * std::tan(outer);
    const glm::vec3 discExtent =
        discRadius * glm::sqrt(glm::max(glm::vec3(1.0f) - axis * axis, glm::vec3(0.0f)));
    box.min = glm::max(box.min, glm::min(instance.position, base - discExtent));
    box.max = glm::min(box.max, glm::max(instance.position, base + discExtent));
    return box;
}

bool binsCovered(const LightVolumeBox& box, const CameraView& camera, const LightBinLayout& layout,
                 glm::uvec3& first, glm::uvec3& last) {
    first = glm::uvec3(0u);
    last = layout.bins - 1u;
    if (box.everywhere) return true;
    // The box's corners in view space: their view depths bound the box's, and, all in front of
    // the near plane, their projections bound its projection.
    float minDepth = 3e38f, maxDepth = -3e38f;
    glm::vec2 ndcMin(3e38f), ndcMax(-3e38f);
    bool allInFront = true;
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner((c & 1) ? box.max.x : box.min.x, (c & 2) ? box.max.y : box.min.y,
                               (c & 4) ? box.max.z : box.min.z);
        const glm::vec4 view = camera.view * glm::vec4(corner, 1.0f);
        const float depth = -view.z;
        minDepth = std::min(minDepth, depth);
        maxDepth = std::max(maxDepth, depth);
        const glm::vec4 clip = camera.projection * view;
        if (!(depth > camera.nearPlane) || !(clip.w > 1e-6f)) {
            allInFront = false;
            continue;
        }
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        ndcMin = glm::min(ndcMin, ndc);
        ndcMax = glm::max(ndcMax, ndc);
    }
    // The view rays start at the camera and go forward: a box wholly behind it is never met.
    if (!(maxDepth > 0.0f)) return false;
    if (allInFront) {
        for (int axis = 0; axis < 2; ++axis) {
            const float lo = elementAt(ndcMin[axis], layout.stride[axis], layout.offset[axis],
                                       layout.extent[axis]);
            const float hi = elementAt(ndcMax[axis], layout.stride[axis], layout.offset[axis],
                                       layout.extent[axis]);
            if (!binRange(lo, hi, layout.elements[axis], layout.perBin[axis], first[axis],
                          last[axis])) {
                return false;
            }
        }
    }
    if (layout.sliced) {
        // Froxel slice s holds view depths [d(s), d(s + 1)], d(b) = near (far / near)^(b / Z)
        // and d(0) = 0; its sample sits inside, so the slices of the box's depths are enough.
        if (minDepth >= layout.farDepth) return false;
        const float z = float(layout.elements.z);
        const float logRatio = std::log(layout.farDepth / layout.nearDepth);
        auto sliceOf = [&](float depth) {
            return depth <= layout.nearDepth ? -1.0f
                                             : z * std::log(depth / layout.nearDepth) / logRatio;
        };
        if (!binRange(sliceOf(minDepth), sliceOf(maxDepth), layout.elements.z, layout.perBin.z,
                      first.z, last.z)) {
            return false;
        }
    }
    return true;
}

bool isPlainMediumLight(const LightInstance& light) {
    const content::LightType type = light.light.type;
    return !light.light.castShadows && type != content::LightType::Directional &&
           type != content::LightType::Rect && type != content::LightType::Disk;
}

std::vector<uint32_t> binLights(std::span<const LightInstance> lights,
                                std::span<const float> scales, const CameraView& camera,
                                const LightBinLayout& layout) {
    const uint32_t binCount = layout.bins.x * layout.bins.y * layout.bins.z;
    struct Covered {
        uint32_t light;
        glm::uvec3 first, last;
    };
    std::vector<Covered> covered;
    std::vector<uint32_t> counts(binCount, 0u);
    for (uint32_t i = 0; i < lights.size(); ++i) {
        if (i >= scales.size() || !(scales[i] > 0.0f)) continue;
        Covered c{i, {}, {}};
        if (!binsCovered(lightVolumeBox(lights[i]), camera, layout, c.first, c.last)) continue;
        for (uint32_t z = c.first.z; z <= c.last.z; ++z)
            for (uint32_t y = c.first.y; y <= c.last.y; ++y)
                for (uint32_t x = c.first.x; x <= c.last.x; ++x)
                    ++counts[(z * layout.bins.y + y) * layout.bins.x + x];
        covered.push_back(c);
    }
    // Plain lights (unshadowed points and spots, spheres, tubes) lead every list, so a shader's
    // first loop takes them with a body that has no shadow or area-light code (lavapipe runs
    // every branch of a body whatever the lanes take); each part stays in light order.
    std::stable_partition(covered.begin(), covered.end(),
                          [&](const Covered& c) { return isPlainMediumLight(lights[c.light]); });
    // Offsets (an exclusive prefix sum of the counts), then each bin's lights in light order.
    std::vector<uint32_t> bins(binCount + 1, 0u);
    for (uint32_t b = 0; b < binCount; ++b)
        bins[b + 1] = bins[b] + counts[b];
    bins.resize(binCount + 1 + bins[binCount]);
    std::vector<uint32_t> next(bins.begin(), bins.begin() + binCount);
    for (const Covered& c : covered) {
        for (uint32_t z = c.first.z; z <= c.last.z; ++z)
            for (uint32_t y = c.first.y; y <= c.last.y; ++y)
                for (uint32_t x = c.first.x; x <= c.last.x; ++x)
                    bins[binCount + 1 + next[(z * layout.bins.y + y) * layout.bins.x + x]++] =
                        c.light;
    }
    return bins;
}

namespace {

// A froxel bin's piece of the view frustum as a sphere in view space: the centre of its eight
// corners and the farthest corner's distance from it.
struct BinSphere {
    glm::vec3 centre{0.0f};
    float radius = 0.0f;
};

BinSphere binSphere(const glm::uvec3& bin, const glm::mat4& inverseProjection,
                    const LightBinLayout& layout) {
    const glm::uvec3 first = bin * layout.perBin;
    const glm::uvec3 end = glm::min(first + layout.perBin, layout.elements);
    const float z = float(layout.elements.z);
    auto depthAt = [&](uint32_t slice) {
        return slice == 0 ? 0.0f
                          : layout.nearDepth *
                                std::pow(layout.farDepth / layout.nearDepth, float(slice) / z);
    };
    glm::vec3 corners[8];
    glm::vec3 centre(0.0f);
    for (int c = 0; c < 8; ++c) {
        const glm::vec2 element((c & 1) ? float(end.x) : float(first.x),
                                (c & 2) ? float(end.y) : float(first.y));
        // An element boundary's NDC (stride 1, edges at element / extent).
        const glm::vec2 ndc = element / layout.extent * 2.0f - 1.0f;
        glm::vec4 near = inverseProjection * glm::vec4(ndc, 1.0f, 1.0f);  // reverse-Z near
        const glm::vec3 perDepth = glm::vec3(near) / near.w / std::max(-near.z / near.w, 1e-6f);
        corners[c] = perDepth * depthAt((c & 4) ? end.z : first.z);
        centre += corners[c] / 8.0f;
    }
    float radius = 0.0f;
    for (const glm::vec3& corner : corners)
        radius = std::max(radius, glm::length(corner - centre));
    return {centre, radius};
}

// What a plain light puts into a bin's air, up to a constant: its luminous intensity x its
// volumetric scale x the falloff window at the bin's nearest point over that distance squared.
float binLightScore(const LightInstance& instance, float scale, const glm::vec3& viewPosition,
                    const BinSphere& sphere) {
    const content::Light& light = instance.light;
    const float distance =
        std::max(glm::length(viewPosition - sphere.centre) - sphere.radius, 0.0f);
    const float range = std::max(light.attenuationRadius, 0.0f);
    if (!(distance < range)) return 0.0f;
    const float ratio = distance / range;
    const float window = (1.0f - ratio * ratio * ratio * ratio);
    const float luminance =
        0.2126f * light.color[0] + 0.7152f * light.color[1] + 0.0722f * light.color[2];
    const float score = std::max(light.lumens, 0.0f) * std::max(luminance, 0.0f) * scale * window *
                        window / (distance * distance + 1e-2f);
    return std::isfinite(score) ? score : 0.0f;
}

}  // namespace

std::vector<uint32_t> capPlainLights(std::span<const uint32_t> bins,
                                     std::span<const LightInstance> lights,
                                     std::span<const float> scales, const CameraView& camera,
                                     const LightBinLayout& layout, uint32_t cap) {
    const uint32_t binCount = layout.bins.x * layout.bins.y * layout.bins.z;
    if (cap == 0 || bins.size() < binCount + 1) return {bins.begin(), bins.end()};
    const glm::mat4 inverseProjection = glm::inverse(camera.projection);
    std::vector<glm::vec3> viewPositions(lights.size());
    for (size_t i = 0; i < lights.size(); ++i)
        viewPositions[i] = glm::vec3(camera.view * glm::vec4(lights[i].position, 1.0f));
    std::vector<uint32_t> out(binCount + 1, 0u);
    std::vector<uint32_t> lists;
    lists.reserve(bins.size() - binCount - 1);
    std::vector<std::pair<float, uint32_t>> scored;
    for (uint32_t b = 0; b < binCount; ++b) {
        const uint32_t* list = bins.data() + binCount + 1 + bins[b];
        const uint32_t count = bins[b + 1] - bins[b];
        uint32_t plain = 0;  // the plain lights lead the list
        while (plain < count && isPlainMediumLight(lights[list[plain]]))
            ++plain;
        if (plain <= cap) {
            lists.insert(lists.end(), list, list + count);
        } else {
            const glm::uvec3 bin(b % layout.bins.x, (b / layout.bins.x) % layout.bins.y,
                                 b / (layout.bins.x * layout.bins.y));
            const BinSphere sphere = binSphere(bin, inverseProjection, layout);
            scored.clear();
            for (uint32_t k = 0; k < plain; ++k) {
                const uint32_t light = list[k];
                const float scale = light < scales.size() ? scales[light] : 0.0f;
                scored.push_back(
                    {binLightScore(lights[light], scale, viewPositions[light], sphere), light});
            }
            // The strongest `cap`, ties to the lower index; then back in light order.
            std::nth_element(scored.begin(), scored.begin() + cap, scored.end(),
                             [](const auto& x, const auto& y) {
                                 return x.first > y.first ||
                                        (x.first == y.first && x.second < y.second);
                             });
            scored.resize(cap);
            std::sort(scored.begin(), scored.end(),
                      [](const auto& x, const auto& y) { return x.second < y.second; });
            for (const auto& kept : scored)
                lists.push_back(kept.second);
            lists.insert(lists.end(), list + plain, list + count);
        }
        out[b + 1] = uint32_t(lists.size());
    }
    out.insert(out.end(), lists.begin(), lists.end());
    return out;
}

uint64_t binnedPairs(std::span<const uint32_t> bins, const LightBinLayout& layout) {
    uint64_t pairs = 0;
    for (uint32_t z = 0; z < layout.bins.z; ++z)
        for (uint32_t y = 0; y < layout.bins.y; ++y)
            for (uint32_t x = 0; x < layout.bins.x; ++x) {
                const glm::uvec3 bin{x, y, z};
                const glm::uvec3 first = bin * layout.perBin;
                const glm::uvec3 inside = glm::min(layout.perBin, layout.elements - first);
                const uint32_t b = (z * layout.bins.y + y) * layout.bins.x + x;
                pairs += uint64_t(bins[b + 1] - bins[b]) * inside.x * inside.y * inside.z;
            }
    return pairs;
}

}  // namespace candela::render
