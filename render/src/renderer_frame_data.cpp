// The renderer's per-frame uploads before its passes are declared
// (Renderer::uploadFrameData): the lights and textured rects' images, the cluster grid's view
// and the camera block (frame_camera.h).

#include "candela/render/renderer.h"
#include "clustered/cluster_light_lists.h"
#include "frame_camera.h"
#include "lights/area_light_textures.h"
#include "lights/gpu_light_buffer.h"
#include "shading_tables.h"

namespace candela::render {

void Renderer::uploadFrameData(const FrameInputs& inputs) {
    const FrameScene& scene = inputs.scene;
    // Textured rects' images first: a changed atlas moves slots, so every light is repacked.
    AreaLightTextures& areaLightTextures = shadingTables_->areaLightTextures();
    const bool texturesMoved = areaLightTextures.update(context_, scene.lights);
    lights_->update(context_, scene.lights, scene.changedLights,
                    scene.lightsRestructured || texturesMoved, &areaLightTextures);
    const CameraView& view = scene.camera;
    clusters_->setView(view, width_, height_);

    camera_->upload(scene, {width_, height_, lights_->count(), lights_->capacity(),
                            options_.aa == AntiAliasing::Taa});
}

}  // namespace candela::render
