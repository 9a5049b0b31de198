#pragma once
// The skinning compute pass (skinning.comp): each frame, every animated draw's deformed
// vertices (morph targets, then linear blend skinning; positions, normals and tangents) are
// written once into the instance's vertex buffer, which the G-buffer, shadow and forward
// passes then bind (SceneResources::vertexBufferOf). Frames with no animated draw declare no
// pass and upload nothing.
#include <span>

#include <glm/glm.hpp>

#include "candela/render/frame_scene.h"
#include "candela/render/gpu_buffer.h"
#include "candela/render/pipeline.h"

namespace candela::render {

class GpuContext;
struct GpuMesh;
class SceneResources;

class SkinningPass {
public:
    explicit SkinningPass(GpuContext& context);

    // The matrices and weights one recordDeform() reads, in buffers the caller keeps alive
    // until the commands ran (counts of 0: no skinning / morphing).
    struct Pose {
        VkBuffer jointMatrices = VK_NULL_HANDLE;  // mat4 array (std430)
        uint32_t firstJoint = 0;
        uint32_t jointCount = 0;
        VkBuffer morphWeights = VK_NULL_HANDLE;  // float array
        uint32_t firstMorphWeight = 0;
        uint32_t morphWeightCount = 0;
    };
    // Deforms `mesh`'s bind-pose vertices by `pose` into `target` (a storage buffer of the
    // mesh's vertex count of MeshVertex). The building block of record(); also for callers
    // that deform into buffers of their own (a previous frame's pose for motion vectors, tests).
    void recordDeform(VkCommandBuffer cmd, const GpuMesh& mesh, const Pose& pose,
                      VkBuffer target) const;

    // Copies the frame's joint matrices and morph weights to the device-visible buffers
    // record() reads; before the frame's commands are submitted.
    void upload(std::span<const glm::mat4> jointMatrices, std::span<const float> morphWeights);
    // Every deform job of `scene`, reading what upload() copied.
    void record(VkCommandBuffer cmd, const FrameScene& scene,
                const SceneResources& resources) const;

    const GpuBuffer& jointBuffer() const { return joints_; }
    const GpuBuffer& morphWeightBuffer() const { return morphWeights_; }

private:
    GpuContext& context_;
    Pipeline pipeline_;
    GpuBuffer joints_;        // host-visible, grows by doubling
    GpuBuffer morphWeights_;  // host-visible, grows by doubling
    GpuBuffer placeholder_;   // bound where a mesh has no skin or no morph targets
};

}  // namespace candela::render
