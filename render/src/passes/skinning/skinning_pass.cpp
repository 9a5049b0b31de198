#include "passes/skinning/skinning_pass.h"

#include <algorithm>
#include <cstring>

#include "candela/render/gpu_context.h"
#include "candela/render/scene_resources.h"
#include "clustered/cluster_light_lists.h"  // ensureHostBuffer
#include "mesh_vertex.h"
#include "passes/skinning/skinning_bindings.h"
#include "shaders/skinning.comp.spv.h"

namespace candela::render {

static_assert(sizeof(MeshVertex) == SKINNING_VERTEX_FLOATS * sizeof(float));
static_assert(offsetof(MeshVertex, normal) == SKINNING_NORMAL_OFFSET * sizeof(float));
static_assert(offsetof(MeshVertex, tangent) == SKINNING_TANGENT_OFFSET * sizeof(float));

namespace {

struct SkinningPush {
    uint32_t vertexCount;
    uint32_t firstJoint;
    uint32_t jointCount;
    uint32_t firstMorphWeight;
    uint32_t morphTargetCount;
};

}  // namespace

SkinningPass::SkinningPass(GpuContext& context) : context_(context) {
    constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;
    const DescriptorBinding bindings[] = {
        {SKINNING_BINDING_SOURCE, kStorage, kCompute},
        {SKINNING_BINDING_SKIN, kStorage, kCompute},
        {SKINNING_BINDING_MORPH_DELTAS, kStorage, kCompute},
        {SKINNING_BINDING_JOINTS, kStorage, kCompute},
        {SKINNING_BINDING_MORPH_WEIGHTS, kStorage, kCompute},
        {SKINNING_BINDING_TARGET, kStorage, kCompute},
    };
    pipeline_ = Pipeline::compute(context, skinning_comp_spv, bindings, sizeof(SkinningPush));
    ensureHostBuffer(context_, placeholder_, 64);
    std::memset(placeholder_.mapped(), 0, placeholder_.size());
    ensureHostBuffer(context_, joints_, sizeof(glm::mat4));
    ensureHostBuffer(context_, morphWeights_, sizeof(float));
}

void SkinningPass::recordDeform(VkCommandBuffer cmd, const GpuMesh& mesh, const Pose& pose,
                                VkBuffer target) const {
    if (mesh.vertexCount == 0) return;
    const bool skinned = mesh.skinVertices.handle() && pose.jointCount > 0 && pose.jointMatrices;
    const uint32_t morphTargets =
        pose.morphWeights ? std::min(mesh.morphTargetCount, pose.morphWeightCount) : 0u;
    const VkBuffer placeholder = placeholder_.handle();
    const VkDescriptorBufferInfo infos[] = {
        {mesh.vertices.handle(), 0, VK_WHOLE_SIZE},
        {skinned ? mesh.skinVertices.handle() : placeholder, 0, VK_WHOLE_SIZE},
        {morphTargets ? mesh.morphDeltas.handle() : placeholder, 0, VK_WHOLE_SIZE},
        {skinned ? pose.jointMatrices : placeholder, 0, VK_WHOLE_SIZE},
        {morphTargets ? pose.morphWeights : placeholder, 0, VK_WHOLE_SIZE},
        {target, 0, VK_WHOLE_SIZE},
    };
    const VkWriteDescriptorSet writes[] = {
        storageBufferWrite(SKINNING_BINDING_SOURCE, &infos[0]),
        storageBufferWrite(SKINNING_BINDING_SKIN, &infos[1]),
        storageBufferWrite(SKINNING_BINDING_MORPH_DELTAS, &infos[2]),
        storageBufferWrite(SKINNING_BINDING_JOINTS, &infos[3]),
        storageBufferWrite(SKINNING_BINDING_MORPH_WEIGHTS, &infos[4]),
        storageBufferWrite(SKINNING_BINDING_TARGET, &infos[5]),
    };
    const SkinningPush push{mesh.vertexCount, pose.firstJoint, skinned ? pose.jointCount : 0u,
                            pose.firstMorphWeight, morphTargets};
    pipeline_.bind(cmd);
    pipeline_.pushDescriptors(cmd, writes);
    pipeline_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, (mesh.vertexCount + SKINNING_GROUP_SIZE - 1) / SKINNING_GROUP_SIZE, 1, 1);
}

void SkinningPass::upload(std::span<const glm::mat4> jointMatrices,
                          std::span<const float> morphWeights) {
    ensureHostBuffer(context_, joints_, jointMatrices.size_bytes());
    ensureHostBuffer(context_, morphWeights_, morphWeights.size_bytes());
    if (!jointMatrices.empty())
        std::memcpy(joints_.mapped(), jointMatrices.data(), jointMatrices.size_bytes());
    if (!morphWeights.empty())
        std::memcpy(morphWeights_.mapped(), morphWeights.data(), morphWeights.size_bytes());
}

void SkinningPass::record(VkCommandBuffer cmd, const FrameScene& scene,
                          const SceneResources& resources) const {
    for (const DeformJob& job : scene.deforms) {
        if (job.target == VK_NULL_HANDLE || job.mesh >= resources.meshCount()) continue;
        const Pose pose{joints_.handle(),       job.firstJoint,       job.jointCount,
                        morphWeights_.handle(), job.firstMorphWeight, job.morphWeightCount};
        recordDeform(cmd, resources.mesh(job.mesh), pose, job.target);
    }
}

}  // namespace candela::render
