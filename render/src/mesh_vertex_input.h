#pragma once
// The vertex input of gbuffer.vert, the vertex stage of every mesh pass (G-buffer, forward
// transparency and its occupancy): binding 0 the interleaved MeshVertex stream; binding 1 a
// second MeshVertex stream of which only the position is read, the previous frame's
// (location 6): an animated draw's last-frame deformed vertices, else the same buffer as
// binding 0 (SceneResources::previousVertexBufferOf), so rigid meshes cost no extra memory.
#include <cstddef>

#include "candela/render/pipeline.h"
#include "mesh_vertex.h"

namespace candela::render {

inline void setMeshVertexInput(GraphicsPipelineDesc& desc) {
    desc.vertexBindings = {{0, sizeof(MeshVertex), VK_VERTEX_INPUT_RATE_VERTEX},
                           {1, sizeof(MeshVertex), VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.vertexAttributes = {
        {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(MeshVertex, position)},
        {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(MeshVertex, normal)},
        {2, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(MeshVertex, tangent)},
        {3, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(MeshVertex, uv0)},
        {4, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(MeshVertex, uv1)},
        {5, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(MeshVertex, color)},
        {6, 1, VK_FORMAT_R32G32B32_SFLOAT, offsetof(MeshVertex, position)},
    };
}

// Binds both streams of `draw`'s vertices (this frame's and last frame's).
inline void bindMeshVertices(VkCommandBuffer cmd, VkBuffer current, VkBuffer previous) {
    const VkBuffer buffers[2] = {current, previous};
    const VkDeviceSize offsets[2] = {0, 0};
    vkCmdBindVertexBuffers(cmd, 0, 2, buffers, offsets);
}

}  // namespace candela::render
