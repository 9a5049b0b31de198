#pragma once
// A temporal feature's history (TAA, SSR's temporal filter, GTAO's accumulation): two images
// written on alternate frames, whether the one written last frame holds a usable history, and
// their import into a frame's graph.
#include <array>
#include <cstdint>
#include <string>

#include "candela/render/gpu_image.h"
#include "frame_graph/frame_graph.h"

namespace candela::render {

class GpuContext;

class TemporalHistory {
public:
    // Both images cleared and shader-readable from the start, so every frame imports them in
    // the same states and the compiled graph is reused from the second frame on (the first
    // frame ignores the history through `valid`, not through a different graph).
    void create(GpuContext& context, const ImageDesc& desc, uint32_t texelBytes);
    // create() unless the images already have desc's format and size (a resize makes new ones).
    void ensure(GpuContext& context, const ImageDesc& desc, uint32_t texelBytes);
    bool created() const { return images_[0].handle() != VK_NULL_HANDLE; }

    // This frame's pair in the graph: last frame's image (sampled by compute, in the state that
    // frame left it) and this frame's (its old contents discarded, left sampled by compute).
    struct Frame {
        ResourceHandle previous;
        ResourceHandle written;
        bool valid = false;  // previous holds the history of an unbroken sequence
    };
    // Declares the pair and flips the images: the next frame reads what this one writes.
    Frame declare(FrameGraph& graph, std::string previousName, std::string writtenName);

    // A frame that does not write the history, a camera cut or a resize breaks the sequence.
    void invalidate() { valid_ = false; }
    bool valid() const { return valid_; }

private:
    std::array<GpuImage, 2> images_;
    uint32_t write_ = 0;
    bool valid_ = false;
};

}  // namespace candela::render
