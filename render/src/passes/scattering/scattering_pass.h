#pragma once
// Light shafts (render/README.md "Light shafts"; issue 16, Yusov 2014, GPU Pro 5, "High Performance
// Outdoor Light Scattering Using Epipolar Sampling", Yusov 2013): the sun's light scattered toward
// the camera by the air, shadowed by the sun's cascades, added to the lit frame, which the air in
// front attenuates. Two modes:
//   epipolar: scattering_coordinates (samples along epipolar lines from the sun to the screen
//     border), scattering_tree (a 1D min/max tree of blocker depths per slice and cascade),
//     scattering_march (the initial samples, every N-th), scattering_refine (more samples
//     where the in-scattering or depth changes by more than a threshold), scattering_interpolate
//     (the others, between their marched neighbours), scattering_unwarp (back to pixels with a
//     depth-aware filter, combined with the attenuated frame);
//   brute-force: scattering_brute_force, every pixel marched in equal steps through every
//     cascade (the reference), in batches of steps under lavapipe's loop limit.
// In frames with blended surfaces or wires, aerial_perspective marches the same air through a
// coarse grid of view rays for them (render/README.md "Aerial perspective").
#include <glm/glm.hpp>

#include "candela/content/components/atmosphere.h"
#include "candela/render/frame_scene.h"
#include "candela/render/gpu_buffer.h"
#include "candela/render/pipeline.h"
#include "candela/render/renderer_options.h"
#include "frame_graph/graph_resources.h"
#include "vk/sampler.h"

namespace candela::render {

class GpuContext;
struct ShadowDescriptors;

class ScatteringPass {
public:
    explicit ScatteringPass(GpuContext& context);

    // The epipolar samples (x: sample, y: slice): coordinates, then in-scattering.
    static ImageDesc samplesDesc(uint32_t slices, uint32_t samplesPerSlice);
    // The trees: a row per slice and cascade, 2 M texels (M leaves, then the levels above).
    static ImageDesc treeDesc(uint32_t slices, uint32_t cascadeSize);
    static VkDeviceSize slicesBytes(uint32_t slices);
    // Leaves per tree: one per texel along the longest line through a cascade (its diagonal),
    // rounded up to a power of two.
    static uint32_t treeLeaves(uint32_t cascadeSize);
    // The aerial-perspective grid (columns, rows, slices) and the bytes of its boundaries in
    // the integrated froxel buffer (one vec4 each).
    static glm::uvec3 aerialGrid(const ScatteringSettings& settings);
    static VkDeviceSize aerialBytes(const ScatteringSettings& settings);

    // The frame's sun (index in the light buffer, -1: none, so no shafts) and the air.
    struct Frame {
        int sunIndex = -1;
        glm::vec2 sunPixel{0.0f};  // the sun's projection (the anti-sun's when behind)
        glm::vec3 rayleigh{0.0f}, mie{0.0f}, extinction{0.0f};  // 1/m
        float mieAnisotropy = 0.8f;
    };
    // The air at the camera's altitude (scaled by settings.densityScale), the first
    // directional light as the sun and its position on a width x height image.
    static Frame frameOf(const FrameScene& scene, const ScatteringSettings& settings,
                         uint32_t width, uint32_t height);

    // Builds the mode's pipelines when first used (or when `shadows` changes), and the aerial
    // perspective's when a frame first needs it.
    void prepare(ScatteringMode mode, bool shadows, bool aerialPerspective);

    struct Inputs {
        ImageRef depth;  // Sampled
        ImageRef hdr;    // StorageReadWrite
        const GpuBuffer* camera = nullptr;
        const GpuBuffer* lights = nullptr;
        uint32_t lightCapacity = 0;
        const ShadowDescriptors* shadows = nullptr;
        bool shadowMaps = false;
        Frame frame;
        ScatteringSettings settings;
        // Epipolar lines and samples per line (RenderSettings::scatteringSlices, ...Samples).
        uint32_t slices = 512, samplesPerSlice = 256;
        uint32_t cascadeSize = 1024;
        float nearPlane = 0.05f;
    };
    void recordCoordinates(VkCommandBuffer cmd, const Inputs& in, const ImageRef& coordinates,
                           const BufferRef& slices) const;
    void recordTree(VkCommandBuffer cmd, const Inputs& in, const BufferRef& slices,
                    const ImageRef& tree) const;
    // phase 0: the initial samples; 1: refinement (depth edges, in-scattering changes); 2:
    // interpolation of the others.
    void recordSamples(VkCommandBuffer cmd, const Inputs& in, uint32_t phase,
                       const ImageRef& coordinates, const BufferRef& slices, const ImageRef& tree,
                       const ImageRef& inscatter) const;
    void recordUnwarp(VkCommandBuffer cmd, const Inputs& in, const BufferRef& slices,
                      const ImageRef& tree, const ImageRef& inscatter) const;
    void recordBruteForce(VkCommandBuffer cmd, const Inputs& in) const;
    // The air's grid for blended surfaces and wires into the integrated froxel buffer
    // `froxels` (common/froxel_grid.glsl), its boundaries from vec4 `firstBoundary`; `fogGrid`
    // false: the frame has no fog grid there, so its head is zeroed.
    void recordAerialPerspective(VkCommandBuffer cmd, const Inputs& in, const BufferRef& froxels,
                                 uint32_t firstBoundary, bool fogGrid) const;

    // Host-visible counters the shaders add to: rays marched, shadow tests taken.
    GpuBuffer& counters() { return counters_; }
    void recordClearCounters(VkCommandBuffer cmd) const;
    struct Counts {
        uint64_t rays = 0, steps = 0;
    };
    Counts readCounters() const;

private:
    GpuContext& context_;
    bool shadows_ = false;
    bool epipolarBuilt_ = false, bruteForceBuilt_ = false, aerialBuilt_ = false;
    Pipeline coordinates_, tree_, samples_, unwarp_, bruteForce_, aerial_;
    Sampler pointSampler_;
    GpuBuffer counters_;
};

}  // namespace candela::render
