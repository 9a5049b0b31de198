#pragma once
// The integrated froxel buffer (common/froxel_grid.glsl) in this frame's graph: the fog's grid
// and the air's aerial-perspective grid that blended surfaces, wires and hair look up (published
// only in frames that have one).
#include "frame_graph/frame_graph.h"

namespace candela::render {

struct IntegratedFroxels {
    ResourceHandle buffer;
};

}  // namespace candela::render
