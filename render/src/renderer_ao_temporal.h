#pragma once
// The renderer's declaration of GTAO's temporal accumulation in a frame's graph, with the
// handles and settings it is given.

#include <cstdint>

#include "frame_graph/frame_graph.h"
#include "passes/ambient_occlusion/ambient_occlusion_pass.h"
#include "temporal_history.h"

namespace candela::render {

// GTAO's temporal accumulation after its denoise (ao_temporal.comp): reads the history
// written last frame, writes the other; returns the accumulated occlusion.
struct AoTemporalDeclaration {
    ResourceHandle current, motion, depth, normal, camera;
    const AmbientOcclusionPass* pass;
    AmbientOcclusionPass::Inputs aoInputs;
    TemporalHistory::Frame history;
    uint32_t maxFrames;
    uint32_t width, height;
};

ResourceHandle declareAoTemporal(FrameGraph& g, const AoTemporalDeclaration& d);

}  // namespace candela::render
