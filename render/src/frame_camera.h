#pragma once
// The camera block every pass reads (gpu_camera.h, camera.glsl) and what motion vectors need of
// the frame before: TAA's sub-pixel jitter (a fixed Halton sequence, so goldens are
// deterministic), last frame's unjittered view-projection and jitter, and each draw's world
// matrix last frame (gbuffer.vert's PREVIOUS_WORLDS_BINDING).
#include <glm/glm.hpp>

#include <cstdint>

#include "candela/render/frame_scene.h"
#include "candela/render/gpu_buffer.h"

namespace candela::render {

class GpuContext;

class FrameCamera {
public:
    explicit FrameCamera(GpuContext& context);

    struct Frame {
        uint32_t width, height;  // the render size
        uint32_t lightCount, lightCapacity;
        bool jitter = false;  // TAA: move the projection by the sequence's next offset
    };
    // Writes this frame's camera block and previous world matrices.
    void upload(const FrameScene& scene, const Frame& frame);
    const GpuBuffer& buffer() const { return buffer_; }
    GpuBuffer& buffer() { return buffer_; }
    const GpuBuffer& previousWorlds() const { return previousWorlds_; }
    // The next frame has no frame before it (a camera cut, a resize): no camera motion, and the
    // jitter sequence starts again.
    void restart();

private:
    GpuContext& context_;
    GpuBuffer buffer_;
    GpuBuffer previousWorlds_;
    glm::mat4 previousViewProjection_{1.0f};
    glm::vec2 previousJitter_{0.0f};
    bool hasPrevious_ = false;
    uint32_t frameIndex_ = 0;  // frames since creation or restart: the jitter's phase
};

}  // namespace candela::render
