#include "passes/volumetrics/integrated_froxels.h"

#include "passes/scattering/scattering_pass.h"
#include "passes/volumetrics/volumetrics_pass.h"
#include "renderer_scene_queries.h"

namespace candela::render {

IntegratedFroxels declareIntegratedFroxels(FrameGraph& graph, const FrameScene& scene,
                                           const RendererOptions& options, uint32_t width,
                                           uint32_t height, bool blended) {
    IntegratedFroxels f;
    f.fogFroxels = scene.fog && (options.volumetrics == VolumetricsMode::Froxels ||
                                 (options.volumetrics == VolumetricsMode::Volumes && blended));
    if (f.fogFroxels)
        f.fogGrid = VolumetricsPass::froxelGrid(width, height, options.volumetricsSettings);
    const bool seenThroughTheGrid = blended || hasWireSegments(scene) || !scene.hair.empty();
    // Froxels march the sun per pixel over their composite, as the per-light volumes march it
    // (a froxel, 8x8 pixels and up to metres deep, is too coarse for shafts through windows):
    // the grid then holds the local lights only, and the sun in a channel of its own for
    // blended surfaces, wires and hair, which the march does not reach (frames with them).
    f.sunMarched = scene.fog && options.volumetrics == VolumetricsMode::Froxels &&
                   VolumetricsPass::sunInMedium(scene.lights);
    f.sunChannel = f.sunMarched && seenThroughTheGrid;
    const VkDeviceSize fogBytes = VolumetricsPass::froxelIntegratedBytes(f.fogGrid, f.sunChannel);
    f.fogBoundaries =
        uint32_t((fogBytes - VolumetricsPass::kFroxelHeaderBytes) / sizeof(glm::vec4));
    f.airFroxels = seenThroughTheGrid && scatteringDrawn(scene, options.scattering);
    if (f.fogFroxels || f.airFroxels) {
        const VkDeviceSize bytes =
            fogBytes + (f.airFroxels ? ScatteringPass::aerialBytes(options.scatteringSettings) : 0);
        f.buffer =
            graph.createBuffer("froxels.integrated", bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    }
    return f;
}

}  // namespace candela::render
