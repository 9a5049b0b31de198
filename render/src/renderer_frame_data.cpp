// The renderer's per-frame uploads before its passes are declared
// (Renderer::uploadFrameData): the lights and textured rects' images, the cluster grid's view,
// the camera block with TAA's jitter and last frame's view-projection, and each draw's
// previous world matrix for motion vectors.

#include <algorithm>
#include <cstring>
#include <glm/glm.hpp>

#include "candela/render/renderer.h"
#include "clustered/cluster_light_lists.h"
#include "gpu_camera.h"
#include "lights/area_light_textures.h"
#include "lights/gpu_light_buffer.h"
#include "passes/taa/taa_pass.h"

namespace candela::render {

void Renderer::uploadFrameData(const FrameInputs& inputs) {
    const FrameScene& scene = inputs.scene;
    // Textured rects' images first: a changed atlas moves slots, so every light is repacked.
    const bool texturesMoved = areaLightTextures_->update(context_, scene.lights);
    lights_->update(context_, scene.lights, scene.changedLights,
                    scene.lightsRestructured || texturesMoved, areaLightTextures_.get());
    const CameraView& view = scene.camera;
    clusters_->setView(view, width_, height_);

    // TAA: the projection moves by a sub-pixel offset from a fixed Halton sequence, so a static
    // image gathers kJitterPhases different samples per pixel (deterministic for goldens).
    glm::vec2 jitter(0.0f);
    if (options_.aa == AntiAliasing::Taa) {
        jitter = {TaaPass::jitterX(frameIndex_), TaaPass::jitterY(frameIndex_)};
    }
    glm::mat4 jitterNdc(1.0f);
    jitterNdc[3][0] = 2.0f * jitter.x / float(width_);
    jitterNdc[3][1] = 2.0f * jitter.y / float(height_);
    const glm::mat4 unjittered = view.projection * view.view;
    GpuCamera camera{};
    camera.viewProjection = jitterNdc * unjittered;
    camera.inverseViewProjection = glm::inverse(camera.viewProjection);
    camera.cameraPosition = glm::vec4(view.position, 1.0f);
    camera.frameInfo = glm::uvec4(width_, height_, lights_->count(), lights_->capacity());
    camera.unjitteredViewProjection = unjittered;
    camera.previousViewProjection = hasPreviousFrame_ ? previousViewProjection_ : unjittered;
    camera.jitter = glm::vec4(jitter, previousJitter_);
    std::memcpy(cameraBuffer_.mapped(), &camera, sizeof(camera));
    previousViewProjection_ = unjittered;
    previousJitter_ = jitter;
    hasPreviousFrame_ = true;
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

}  // namespace candela::render
