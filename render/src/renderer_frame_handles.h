#pragma once
// The renderer's per-frame handles that its frame declarations (renderer.cpp and the
// renderer_*.cpp files beside it) hand to each other: resource ids in this frame's graph,
// valid only while that frame is declared.

#include <array>
#include <cstdint>

#include "candela/render/renderer.h"
#include "clustered/cluster_light_lists.h"
#include "frame_graph/frame_graph.h"

namespace candela::render {

// The handles of one frame's scene passes. Passes capture resource ids by value; the
// versions they read are declared through the builder.
struct Renderer::SceneHandles {
    std::array<ResourceHandle, 4> color;
    ResourceHandle depth, motion, hdr, camera, lights;
    ClusterLightLists::Lists clusters;
    bool extended = false;  // the anisotropy and clear-coat targets (gbuffer_targets.h)
    ResourceHandle anisotropy, clearCoat;
    bool hasEdges = false;       // GBAA's edge target (--aa gbaa; gbuffer_targets.h)
    bool separateEdges = false;  // written by its own pass (GBufferPass::separateEdges)
    ResourceHandle edges;
};

}  // namespace candela::render
