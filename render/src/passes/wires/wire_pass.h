#pragma once
// Wires (Persson 2014, GPU Pro 5, "Wire Antialiasing"): thin cylinders along polylines
// (content/wire.h), drawn after the lit frame and its volumetrics, before the blended surfaces, as
// camera-facing quads at least a pixel wide whose alpha carries the real width (Persson's
// phone-wire antialiasing), with coverage from the distance to the centre line and shading that
// bends thin wires' normals toward the camera (wire.vert, wire.frag). Depth-tested against the
// G-buffer depth, not written; lit by the clustered lights and the sky like the forward transparent
// pass.
#include <glm/glm.hpp>
#include <vector>

#include "candela/render/frame_scene.h"
#include "candela/render/gpu_buffer.h"
#include "candela/render/pipeline.h"
#include "candela/render/renderer_options.h"
#include "frame_graph/graph_resources.h"
#include "passes/lighting/lighting_pass.h"

namespace candela::render {

class GpuContext;
struct ClusterGrid;
struct EnvironmentDescriptors;
struct ShadowDescriptors;

class WirePass {
public:
    explicit WirePass(GpuContext& context);
    ~WirePass();
    WirePass(const WirePass&) = delete;
    WirePass& operator=(const WirePass&) = delete;

    // Writes the frame's segments in world space (one frame is in flight at a time, so the
    // buffer is free) and selects the shader variant. False when there is no segment: the
    // frame then records nothing of this pass.
    bool prepare(const FrameScene& scene, const LightingFeatures& features, WireMode mode);
    uint32_t segmentCount() const { return segmentCount_; }

    // hdr: ColorAttachment (blended over); depth: DepthRead attachment; the light lists and
    // depthRange are read in the fragment shader.
    struct Inputs {
        ImageRef hdr;
        ImageRef depth;
        LitInputs lit;
        float pixelRadiusPerDepth;  // 1 / (projection[1][1] x target height)
        float nearPlane;
        // Froxels (passes/volumetrics), read in the fragment shader; null: no medium.
        bool froxels = false;  // froxelIntegrated holds the frame's grid
        BufferRef froxelIntegrated;
    };
    void record(VkCommandBuffer cmd, const Inputs& in) const;

private:
    void buildPipeline();

    GpuContext& context_;
    GpuBuffer segments_;
    // Zeros: an integrated froxel buffer whose header says "no medium", bound when the frame has no
    // froxels.
    GpuBuffer noMedium_;
    uint32_t segmentCount_ = 0;
    WireMode mode_ = WireMode::Coverage;
    LightingFeatures features_;
    bool built_ = false;
    Pipeline pipeline_;
};

}  // namespace candela::render
