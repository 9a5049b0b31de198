#pragma once
// The lit inputs: what every pass that lights surfaces reads beside its own inputs (the deferred
// lighting, hair, wires and blended surfaces). The camera, the lights and their cluster lists,
// the shadow maps, the sky (prefiltered cube, BRDF LUT, irradiance), the area lights' tables and
// sky occlusion. One struct for the device objects, one for their frame-graph handles with the
// reads a lit pass declares, and one binder: every lit pipeline binds them at the numbers of
// common/lit_bindings.h (shaders declare them through common/lit_inputs.glsl).
#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "candela/render/pipeline.h"
#include "clustered/cluster_light_lists.h"
#include "frame_graph/frame_graph.h"
#include "ibl/environment_descriptors.h"
#include "passes/shadows/shadow_descriptors.h"

namespace candela::render {

// Made when the frame is declared and copied into the passes' record callbacks.
struct LitInputs {
    const GpuBuffer* camera = nullptr;
    const GpuBuffer* lights = nullptr;
    // Its lists, grid and directional count are read when a pass records: the CPU assignment
    // sizes the lists in its host pass, after the frame is declared.
    const ClusterLightLists* clusters = nullptr;
    EnvironmentDescriptors environment{};  // the sky, or placeholders
    float skyIntensity = 1.0f;
    ShadowDescriptors shadows{};           // the atlas and tables, or placeholders
    VkDescriptorImageInfo skyOcclusion{};  // SkyOcclusionPass::descriptor (a placeholder when off)
};

// The lit inputs in this frame's graph.
struct LitInputHandles {
    ResourceHandle camera, lights;
    bool clustered = false;
    ClusterLightLists::Lists clusters;
    bool shadows = false;
    ResourceHandle shadowAtlas, shadowViews, shadowLights;
    bool skyOcclusion = false;
    ResourceHandle skyOcclusionAtlas;
    // The reads of a pass that binds them in `stages` (the camera it reads as it declares).
    void declareReads(FrameGraph::PassBuilder& pass, VkPipelineStageFlags2 stages) const;
};

// What the renderer publishes for the lit features (FrameBlackboard).
struct LitFrame {
    LitInputs inputs;
    LitInputHandles reads;
    uint32_t lightCount = 0;     // lights in inputs.lights
    uint32_t lightCapacity = 0;  // lights its streams hold room for
    bool brdfLut = false;        // inputs.environment.brdfLut is the LUT, not its placeholder
};

// A lit pipeline's layout: its own bindings, then the lit inputs' (camera and lights included),
// visible to `stages`.
std::vector<DescriptorBinding> withLitInputBindings(std::span<const DescriptorBinding> own,
                                                    VkShaderStageFlags stages);

// A lit pass's descriptor writes: its own, then the lit inputs', with the buffer infos they
// point at. Lives while the writes are pushed.
class LitDescriptorWrites {
public:
    LitDescriptorWrites(const LitInputs& in, std::span<const VkWriteDescriptorSet> own);
    LitDescriptorWrites(const LitDescriptorWrites&) = delete;
    LitDescriptorWrites& operator=(const LitDescriptorWrites&) = delete;
    std::span<const VkWriteDescriptorSet> writes() const { return writes_; }

private:
    std::array<VkDescriptorBufferInfo, 5>
        buffers_{};  // camera, lights, ranges, indices, depth range
    std::vector<VkWriteDescriptorSet> writes_;
};

}  // namespace candela::render
