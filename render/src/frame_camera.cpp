#include "frame_camera.h"

#include <algorithm>
#include <cstring>

#include "clustered/cluster_light_lists.h"
#include "gpu_camera.h"
#include "passes/taa/taa_pass.h"

namespace candela::render {

FrameCamera::FrameCamera(GpuContext& context)
    : context_(context),
      buffer_(context, sizeof(GpuCamera), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
              MemoryLocation::HostVisible) {}

void FrameCamera::upload(const FrameScene& scene, const Frame& frame) {
    const CameraView& view = scene.camera;
    // TAA: the projection moves by a sub-pixel offset from a fixed Halton sequence, so a static
    // image gathers kJitterPhases different samples per pixel (deterministic for goldens).
    glm::vec2 jitter(0.0f);
    if (frame.jitter) jitter = {TaaPass::jitterX(frameIndex_), TaaPass::jitterY(frameIndex_)};
    glm::mat4 jitterNdc(1.0f);
    jitterNdc[3][0] = 2.0f * jitter.x / float(frame.width);
    jitterNdc[3][1] = 2.0f * jitter.y / float(frame.height);
    const glm::mat4 unjittered = view.projection * view.view;
    GpuCamera camera{};
    camera.viewProjection = jitterNdc * unjittered;
    camera.inverseViewProjection = glm::inverse(camera.viewProjection);
    camera.cameraPosition = glm::vec4(view.position, 1.0f);
    camera.frameInfo = glm::uvec4(frame.width, frame.height, frame.lightCount, frame.lightCapacity);
    camera.unjitteredViewProjection = unjittered;
    camera.previousViewProjection = hasPrevious_ ? previousViewProjection_ : unjittered;
    camera.jitter = glm::vec4(jitter, previousJitter_);
    std::memcpy(buffer_.mapped(), &camera, sizeof(camera));
    previousViewProjection_ = unjittered;
    previousJitter_ = jitter;
    hasPrevious_ = true;
    ++frameIndex_;

    // Each draw's world matrix last frame: given by the caller (moving objects), else its
    // current one (no motion of its own).
    ensureHostBuffer(context_, previousWorlds_,
                     std::max<size_t>(scene.draws.size(), 1) * sizeof(glm::mat4));
    auto* previous = static_cast<glm::mat4*>(previousWorlds_.mapped());
    const bool given = scene.previousWorlds.size() == scene.draws.size();
    for (size_t i = 0; i < scene.draws.size(); ++i)
        previous[i] = given ? scene.previousWorlds[i] : scene.draws[i].world;
}

void FrameCamera::restart() {
    hasPrevious_ = false;
    frameIndex_ = 0;
}

}  // namespace candela::render
