#include "passes/shadows/caster_depth_draws.h"

#include "candela/render/frame_scene.h"
#include "candela/render/pipeline.h"
#include "candela/render/scene_resources.h"

namespace candela::render {

void drawCasterDepths(VkCommandBuffer cmd, const Pipeline& pipeline, const FrameScene& scene,
                      const SceneResources& resources, std::span<const uint32_t> casters,
                      const glm::mat4& viewToClip, std::span<const uint8_t> lods) {
    for (size_t c = 0; c < casters.size(); ++c) {
        const DrawItem& draw = scene.draws[casters[c]];
        const GpuMesh& mesh = resources.mesh(draw.mesh);
        const glm::mat4 worldToClip = viewToClip * draw.world;
        pipeline.pushConstants(cmd, &worldToClip, sizeof(worldToClip));
        const VkDeviceSize offset = 0;
        const VkBuffer vertexBuffer = resources.vertexBufferOf(draw);
        vkCmdBindVertexBuffers(cmd, 0, 1, &vertexBuffer, &offset);
        vkCmdBindIndexBuffer(cmd, mesh.indices.handle(), 0, VK_INDEX_TYPE_UINT32);
        const GpuMesh::Lod& level = mesh.lods[lods.empty() ? 0 : lods[c]];
        vkCmdDrawIndexed(cmd, level.indexCount, 1, level.firstIndex, 0, 0);
    }
}

}  // namespace candela::render
