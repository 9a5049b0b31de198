#pragma once
// Which lights reach which part of the screen, for the volumetric lighting shaders (issue 17,
// render/README.md "Volumetric lighting"): Vos 2014, GPU Pro 5, "Volumetric Light Effects in
// Killzone: Shadow Fall" has each light render its volume (a sphere for a point light, a cone for a
// spot, the whole screen for the sun) so that a light costs only the pixels it covers. Here each
// light's volume is bounded on the CPU (a box around its range sphere, or around its cone cut at
// its range; everywhere for the sun and for a volume that reaches behind the near plane, such as
// one holding the camera), the box projected to the screen, and the light listed in every
// workgroup's bin that the projection covers: an 8x8 tile of the per-light volumes' half-resolution
// march, or a 4x4x4 cluster of froxels (its slices from the box's view depths too). A shader
// invocation then loops over its workgroup's list only: the proxy mesh's per-pixel coverage at tile
// granularity, with neither rasterisation nor the shared memory and barriers that made GPU-built
// lists cost more than they saved on lavapipe.
//
// Buffer layout (light_bins.glsl): for B bins, B + 1 offsets into the list that follows them
// (bin b's lights are list[offset[b], offset[b + 1])), the plain lights first, then the others,
// each part in ascending light index.
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "candela/render/frame_scene.h"

namespace candela::render {

// Workgroups of the binned dispatch: bins across, down and deep (1 deep for a screen-tile
// dispatch), each covering `pixels` of the binned resolution across and down and, for froxels,
// `slices` depth slices.
struct LightBinLayout {
    glm::uvec3 bins{1u};
    // Binned elements (half-resolution pixels or froxels) across, down, deep, and per bin.
    glm::uvec3 elements{1u};
    glm::uvec3 perBin{8u, 8u, 1u};
    // How an element's centre maps to NDC: ndc = (element * stride + offset) / extent * 2 - 1
    // (half-resolution pixel q samples full pixel 2q: stride 2, offset 0.5, extent the width).
    glm::vec2 stride{1.0f}, offset{0.5f}, extent{1.0f};
    // Froxels: view depths of the exponential slicing (volumetrics_push.glsl sliceBoundaryDepth).
    float nearDepth = 0.05f, farDepth = 100.0f;
    bool sliced = false;
};

// The per-light volumes' march: 8x8 half-resolution pixels per bin, at full size width x height.
LightBinLayout volumeTileLayout(uint32_t width, uint32_t height);
// The froxel lighting: 4x4x4 froxels per bin of the grid, slices from nearDepth to farDepth.
LightBinLayout froxelClusterLayout(const glm::uvec3& grid, float nearDepth, float farDepth);

// A light's volume as a world-space box, or everywhere (the sun, a range of zero or less).
struct LightVolumeBox {
    bool everywhere = false;
    glm::vec3 min{0.0f}, max{0.0f};
};
LightVolumeBox lightVolumeBox(const LightInstance& light);

// The bins `box` covers, as a range [first, last] per axis; false when it covers none (behind
// the camera, beside the view, beyond the last slice).
bool binsCovered(const LightVolumeBox& box, const CameraView& camera, const LightBinLayout& layout,
                 glm::uvec3& first, glm::uvec3& last);

// A light the volumetric shaders' first loop takes (no shadow, not directional, not a rect or
// disk): each bin lists these first.
bool isPlainMediumLight(const LightInstance& light);

// Lists per bin (the layout at the top) of the lights whose `scales` entry is positive, the
// plain ones first (isPlainMediumLight), each part in ascending light index.
std::vector<uint32_t> binLights(std::span<const LightInstance> lights,
                                std::span<const float> scales, const CameraView& camera,
                                const LightBinLayout& layout);

// A per-bin light cap (the froxel lighting's; the quality presets' froxelLightCap): in each bin
// of `bins` (binLights' buffer for `layout`) that lists more than `cap` plain lights, only the
// `cap` of them that put the most light into the bin's air stay: intensity x volumetric scale
// x the falloff window at the bin's nearest point, over that distance squared (the bin's
// frustum piece bounded by a sphere). The lights that are not plain (shadowed, rect and disk,
// the sun) all stay; each part keeps its light order. 0: no cap.
std::vector<uint32_t> capPlainLights(std::span<const uint32_t> bins,
                                     std::span<const LightInstance> lights,
                                     std::span<const float> scales, const CameraView& camera,
                                     const LightBinLayout& layout, uint32_t cap);

// Element-light pairs of `bins` (binLights' buffer for `layout`): each bin's list length times
// the elements (pixels, froxels) of the bin inside the layout's extent. What a binned shader
// evaluates: the frame budget's work count.
uint64_t binnedPairs(std::span<const uint32_t> bins, const LightBinLayout& layout);

}  // namespace candela::render
