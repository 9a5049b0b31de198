#pragma once
// The physically based sky (issue 16; Hillaire 2020, render/README.md "Atmosphere"):
//   atmosphere_transmittance, atmosphere_multiple_scattering: the two tables that depend on the
//     atmosphere alone, made when it changes (the first frame);
//   atmosphere_sky_view: the sky seen from the viewer, every frame (the sun moves);
//   atmosphere_ibl: the sky as an environment cube, filtered for image-based lighting
//     (ibl/environment_filter.h) into the one of two environments the frame does not light
//     with, one step per frame (cube and mips, prefilter, irradiance), then swapped in: a sun
//     that moves re-lights the scene three frames later at a third of the cost per frame. The
//     first frame does all three steps at once;
//   atmosphere_sky: the background (sky and the sun's disc) after lighting.
// Why Hillaire's tables rather than Bruneton 2008's 4D scattering table: no 4D table to
// precompute (the two sun-independent tables take one dispatch each, the sky-view table is
// 192x108 texels per frame), so a moving sun and a day cycle cost the same every frame; and
// the multiple-scattering approximation (an isotropic infinite series per altitude and sun
// angle) stays within a few percent of path-traced skies (Hillaire 2020 section 6).
#include <glm/glm.hpp>
#include <memory>

#include "candela/content/components/atmosphere.h"
#include "candela/render/environment.h"
#include "candela/render/frame_scene.h"
#include "candela/render/gpu_image.h"
#include "candela/render/pipeline.h"
#include "candela/render/renderer_options.h"
#include "frame_graph/frame_graph.h"
#include "frame_graph/graph_resources.h"
#include "ibl/environment_filter.h"
#include "passes/atmosphere/atmosphere_parameters.h"
#include "vk/sampler.h"

namespace candela::render {

class GpuBuffer;
class GpuContext;

class AtmospherePass {
public:
    AtmospherePass(GpuContext& context, const AtmosphereSettings& settings);
    ~AtmospherePass();

    struct Frame {
        content::Atmosphere atmosphere;
        glm::vec3 towardSun{0.0f, 1.0f, 0.0f};  // unit, world (+Y up)
        float viewerAltitude = 1.0f;            // metres above the ground (camera y)
    };
    // The frame's atmosphere, sun (its first directional light, reversed) and viewer.
    static Frame frameOf(const FrameScene& scene);
    // Declares this frame's table, sky-view and image-based lighting passes and decides which
    // environment the frame lights with (environment()). Call before the scene's passes.
    void declareTables(FrameGraph& graph, const Frame& frame);
    // The environment the frame's lighting samples (the last finished sky cube).
    std::shared_ptr<const Environment> environment() const { return front_; }
    // False while that cube is rendered in this very frame (the first one): nothing on the
    // CPU can read it yet (the reference IBL's sampling table does).
    bool environmentReadable() const { return front_ && !frontRenderedThisFrame_; }
    // The sky background over the lit target (pixels at depth 0), after lighting.
    ResourceHandle declareBackground(FrameGraph& graph, ResourceHandle camera, ResourceHandle depth,
                                     ResourceHandle hdr, const GpuBuffer& cameraBuffer);

    // Which image-based-lighting step the last frame ran (0: none, 1..3), for tests.
    uint32_t lastIblStep() const { return lastIblStep_; }
    const GpuImage& skyView() const { return skyView_; }
    const GpuImage& transmittance() const { return transmittance_; }

private:
    struct Push {
        GpuAtmosphere atmosphere;
        glm::vec4 sun;    // towards the sun, viewer radius (km)
        glm::uvec4 size;  // image size, samples, cube face
    };
    struct Cube {
        std::shared_ptr<Environment> environment;
        std::unique_ptr<EnvironmentViews> views;
    };
    Push push(glm::uvec2 size, uint32_t steps) const;
    void recordIblStep(VkCommandBuffer cmd, uint32_t step, const ImageRef& skyView,
                       const Push& push, uint32_t cube) const;

    GpuContext& context_;
    AtmosphereSettings settings_;
    Sampler linear_;
    Sampler nearest_;  // the depth (D32 has no linear filtering)
    Pipeline transmittancePipeline_;
    Pipeline multiplePipeline_;
    Pipeline skyViewPipeline_;
    Pipeline cubePipeline_;
    Pipeline backgroundPipeline_;
    EnvironmentFilter filter_;
    GpuImage transmittance_;
    GpuImage multipleScattering_;
    GpuImage skyView_;
    bool tablesValid_ = false;
    bool skyViewValid_ = false;
    content::Atmosphere tablesFor_;
    // This frame's parameters and handles (declareTables -> declareBackground).
    GpuAtmosphere atmosphere_{};
    glm::vec4 sun_{0.0f};
    ResourceHandle transmittanceHandle_, skyViewHandle_;
    // Image-based lighting: the environment lit with, the one being made, the step it is at
    // (0: idle) and the sun and viewer it is made for.
    std::shared_ptr<Environment> front_;
    Cube cubes_[2];
    uint32_t back_ = 0;
    uint32_t step_ = 0;
    uint32_t lastIblStep_ = 0;
    bool frontRenderedThisFrame_ = false;
    glm::vec4 iblSun_{0.0f};
    content::Atmosphere iblFor_;
};

}  // namespace candela::render
