#pragma once
// The integrated froxel buffer (common/froxel_grid.glsl) of a frame: the fog's grid (froxel
// volumetrics; blended surfaces under per-light volumes) and the air's aerial-perspective grid
// (blended surfaces, wires and hair under an atmosphere's shafts), in frames that have them; one
// buffer, so its readers need one binding. Wires and hair under per-light volumes read no fog
// grid: lighting the demo's, made only for its power lines, cost 14x the volumes' march.
#include <glm/glm.hpp>

#include <cstdint>
#include <optional>

#include "candela/render/frame_scene.h"
#include "candela/render/renderer_options.h"
#include "frame_graph/frame_graph.h"

namespace candela::render {

struct IntegratedFroxels {
    // The buffer's latest version (volumetrics and the aerial perspective write it); none:
    // nothing in the frame reads a grid.
    std::optional<ResourceHandle> buffer;
    bool fogFroxels = false;     // the fog's grid is lit (froxel volumetrics, or for blended)
    glm::uvec3 fogGrid{0u};      // its size (0 without it)
    bool sunMarched = false;     // froxel volumetrics march the sun per pixel over the grid
    bool sunChannel = false;     // ... and the grid holds it too, for what the march misses
    bool airFroxels = false;     // the aerial-perspective grid follows the fog's
    uint32_t fogBoundaries = 0;  // the fog grid's vec4 entries before the air's
};

// The frame's plan and, when something reads a grid, its transient buffer. `blended`: the frame
// has blended draws.
IntegratedFroxels declareIntegratedFroxels(FrameGraph& graph, const FrameScene& scene,
                                           const RendererOptions& options, uint32_t width,
                                           uint32_t height, bool blended);

}  // namespace candela::render
