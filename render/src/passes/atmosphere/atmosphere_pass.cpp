#include "passes/atmosphere/atmosphere_pass.h"

#include <algorithm>
#include <cmath>

#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_context.h"
#include "common/shared_bindings.h"
#include "frame_graph/frame_graph_executor.h"
#include "passes/atmosphere/atmosphere_bindings.h"
#include "shaders/atmosphere_multiple_scattering.comp.spv.h"
#include "shaders/atmosphere_sky.comp.spv.h"
#include "shaders/atmosphere_sky_cube.comp.spv.h"
#include "shaders/atmosphere_sky_view.comp.spv.h"
#include "shaders/atmosphere_transmittance.comp.spv.h"

namespace candela::render {

namespace {

constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;
constexpr VkFormat kTableFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
constexpr ImageState kSampled{VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                              VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                              VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};

uint32_t groups(uint32_t count) {
    return (count + ATMOSPHERE_GROUP_SIZE - 1) / ATMOSPHERE_GROUP_SIZE;
}

GpuImage table(GpuContext& context, uint32_t width, uint32_t height) {
    return GpuImage(context, {kTableFormat, std::max(width, 1u), std::max(height, 1u), 1, false,
                              VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                  VK_IMAGE_USAGE_TRANSFER_SRC_BIT});
}

constexpr DescriptorBinding sampled(uint32_t binding) {
    return {binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute};
}
constexpr DescriptorBinding storage(uint32_t binding) {
    return {binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute};
}

}  // namespace

AtmospherePass::AtmospherePass(GpuContext& context, const AtmosphereSettings& settings)
    : context_(context),
      settings_(settings),
      linear_(context, SamplerDesc{VK_FILTER_LINEAR, false}),
      nearest_(context, SamplerDesc{VK_FILTER_NEAREST}),
      filter_(context) {
    const uint32_t pushBytes = sizeof(Push);
    const DescriptorBinding transmittance[] = {storage(ATMOSPHERE_BINDING_DESTINATION)};
    transmittancePipeline_ =
        Pipeline::compute(context, atmosphere_transmittance_comp_spv, transmittance, pushBytes);
    const DescriptorBinding multiple[] = {sampled(ATMOSPHERE_BINDING_TRANSMITTANCE),
                                          storage(ATMOSPHERE_BINDING_DESTINATION)};
    multiplePipeline_ =
        Pipeline::compute(context, atmosphere_multiple_scattering_comp_spv, multiple, pushBytes);
    const DescriptorBinding skyView[] = {sampled(ATMOSPHERE_BINDING_TRANSMITTANCE),
                                         sampled(ATMOSPHERE_BINDING_MULTIPLE_SCATTERING),
                                         storage(ATMOSPHERE_BINDING_DESTINATION)};
    skyViewPipeline_ = Pipeline::compute(context, atmosphere_sky_view_comp_spv, skyView, pushBytes);
    const DescriptorBinding cube[] = {sampled(ATMOSPHERE_BINDING_SKY_VIEW),
                                      storage(ATMOSPHERE_BINDING_DESTINATION)};
    cubePipeline_ = Pipeline::compute(context, atmosphere_sky_cube_comp_spv, cube, pushBytes);
    const DescriptorBinding background[] = {
        {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kCompute},
        sampled(ATMOSPHERE_BINDING_TRANSMITTANCE),
        sampled(ATMOSPHERE_BINDING_SKY_VIEW),
        sampled(ATMOSPHERE_BINDING_DEPTH),
        storage(ATMOSPHERE_BINDING_HDR)};
    backgroundPipeline_ =
        Pipeline::compute(context, atmosphere_sky_comp_spv, background, pushBytes);
    transmittance_ = table(context, settings.transmittanceWidth, settings.transmittanceHeight);
    multipleScattering_ =
        table(context, settings.multipleScatteringSize, settings.multipleScatteringSize);
    skyView_ = table(context, settings.skyViewWidth, settings.skyViewHeight);
}

AtmospherePass::~AtmospherePass() = default;

AtmospherePass::Frame AtmospherePass::frameOf(const FrameScene& scene) {
    Frame frame;
    if (scene.atmosphere) frame.atmosphere = *scene.atmosphere;
    for (const LightInstance& l : scene.lights) {
        if (l.light.type == content::LightType::Directional) {
            frame.towardSun = -l.direction;
            break;
        }
    }
    frame.viewerAltitude = scene.camera.position.y;
    return frame;
}

AtmospherePass::Push AtmospherePass::push(glm::uvec2 size, uint32_t steps) const {
    return {atmosphere_, sun_, glm::uvec4(size, std::max(steps, 1u), settings_.cubeFaceSize)};
}

void AtmospherePass::declareTables(FrameGraph& g, const Frame& frame) {
    atmosphere_ = gpuAtmosphere(frame.atmosphere);
    // The viewer's radius (km), at least half a metre above the ground and inside the air.
    const float radius =
        std::min(atmosphere_.radii.x + std::max(frame.viewerAltitude, 0.5f) * 1e-3f,
                 atmosphere_.radii.y - 1e-2f);
    const float length = glm::length(frame.towardSun);
    const glm::vec3 towardSun =
        length > 0.0f && std::isfinite(length) ? frame.towardSun / length : glm::vec3(0, 1, 0);
    sun_ = glm::vec4(towardSun, radius);

    const bool tablesDue = !tablesValid_ || !(frame.atmosphere == tablesFor_);
    transmittanceHandle_ = g.importImage("atmosphere.transmittance", &transmittance_,
                                         tablesValid_ ? kSampled : ImageState{}, kSampled);
    ResourceHandle multiple = g.importImage("atmosphere.multiple_scattering", &multipleScattering_,
                                            tablesValid_ ? kSampled : ImageState{}, kSampled);
    skyViewHandle_ = g.importImage("atmosphere.sky_view", &skyView_,
                                   skyViewValid_ ? kSampled : ImageState{}, kSampled);
    if (tablesDue) {
        const Push pt = push({settings_.transmittanceWidth, settings_.transmittanceHeight},
                             settings_.transmittanceSteps);
        const ResourceHandle t = transmittanceHandle_;
        auto p = g.addPass("atmosphere_transmittance", PassKind::Device,
                           [this, t, pt](PassContext& ctx) {
                               VkDescriptorImageInfo out{VK_NULL_HANDLE, ctx.image(t).view(),
                                                         VK_IMAGE_LAYOUT_GENERAL};
                               VkWriteDescriptorSet writes[] = {
                                   storageImageWrite(ATMOSPHERE_BINDING_DESTINATION, &out)};
                               transmittancePipeline_.bind(ctx.cmd());
                               transmittancePipeline_.pushDescriptors(ctx.cmd(), writes);
                               transmittancePipeline_.pushConstants(ctx.cmd(), &pt, sizeof(pt));
                               vkCmdDispatch(ctx.cmd(), groups(pt.size.x), groups(pt.size.y), 1);
                           });
        transmittanceHandle_ = p.write(transmittanceHandle_, Use::StorageWrite);
        const ResourceHandle tRead = transmittanceHandle_;
        const Push pm = push({settings_.multipleScatteringSize, settings_.multipleScatteringSize},
                             settings_.multipleScatteringSteps);
        auto m = g.addPass("atmosphere_multiple_scattering", PassKind::Device,
                           [this, tRead, multiple, pm](PassContext& ctx) {
                               VkDescriptorImageInfo in{linear_.handle(), ctx.image(tRead).view(),
                                                        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
                               VkDescriptorImageInfo out{VK_NULL_HANDLE, ctx.image(multiple).view(),
                                                         VK_IMAGE_LAYOUT_GENERAL};
                               VkWriteDescriptorSet writes[] = {
                                   sampledImageWrite(ATMOSPHERE_BINDING_TRANSMITTANCE, &in),
                                   storageImageWrite(ATMOSPHERE_BINDING_DESTINATION, &out)};
                               multiplePipeline_.bind(ctx.cmd());
                               multiplePipeline_.pushDescriptors(ctx.cmd(), writes);
                               multiplePipeline_.pushConstants(ctx.cmd(), &pm, sizeof(pm));
                               vkCmdDispatch(ctx.cmd(), groups(pm.size.x), groups(pm.size.y), 1);
                           });
        m.read(transmittanceHandle_, Use::Sampled);
        multiple = m.write(multiple, Use::StorageWrite);
        tablesValid_ = true;
        tablesFor_ = frame.atmosphere;
    }
    {
        const ResourceHandle t = transmittanceHandle_, ms = multiple, sv = skyViewHandle_;
        const Push ps =
            push({settings_.skyViewWidth, settings_.skyViewHeight}, settings_.skyViewSteps);
        auto p = g.addPass("atmosphere_sky_view", PassKind::Device,
                           [this, t, ms, sv, ps](PassContext& ctx) {
                               VkDescriptorImageInfo tIn{linear_.handle(), ctx.image(t).view(),
                                                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
                               VkDescriptorImageInfo msIn{linear_.handle(), ctx.image(ms).view(),
                                                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
                               VkDescriptorImageInfo out{VK_NULL_HANDLE, ctx.image(sv).view(),
                                                         VK_IMAGE_LAYOUT_GENERAL};
                               VkWriteDescriptorSet writes[] = {
                                   sampledImageWrite(ATMOSPHERE_BINDING_TRANSMITTANCE, &tIn),
                                   sampledImageWrite(ATMOSPHERE_BINDING_MULTIPLE_SCATTERING, &msIn),
                                   storageImageWrite(ATMOSPHERE_BINDING_DESTINATION, &out)};
                               skyViewPipeline_.bind(ctx.cmd());
                               skyViewPipeline_.pushDescriptors(ctx.cmd(), writes);
                               skyViewPipeline_.pushConstants(ctx.cmd(), &ps, sizeof(ps));
                               vkCmdDispatch(ctx.cmd(), groups(ps.size.x), groups(ps.size.y), 1);
                           });
        p.read(transmittanceHandle_, Use::Sampled);
        p.read(multiple, Use::Sampled);
        skyViewHandle_ = p.write(skyViewHandle_, Use::StorageWrite);
        skyViewValid_ = true;
    }

    // Image-based lighting: start a new sky cube when the sun, the viewer or the atmosphere
    // moved since the last one; advance the one under way by a step (all three at first).
    lastIblStep_ = 0;
    const bool first = !front_;
    frontRenderedThisFrame_ = first;
    if (step_ == 0) {
        const float cosMoved = glm::dot(glm::vec3(iblSun_), glm::vec3(sun_));
        const bool moved = cosMoved < std::cos(glm::radians(settings_.iblUpdateDegrees)) ||
                           std::abs(iblSun_.w - sun_.w) > 0.05f || !(frame.atmosphere == iblFor_);
        if (first || moved) {
            step_ = 1;
            iblSun_ = sun_;
            iblFor_ = frame.atmosphere;
        }
    }
    if (step_ == 0) return;
    Cube& cube = cubes_[back_];
    if (!cube.environment) {
        cube.environment = Environment::forDevice(context_, settings_.cubeFaceSize, "atmosphere");
        cube.views = std::make_unique<EnvironmentViews>(context_, cube.environment->cube(),
                                                        cube.environment->prefiltered());
    }
    const uint32_t firstStep = step_;
    const uint32_t lastStep = first ? 3u : step_;
    Push pc = push({settings_.cubeFaceSize, settings_.cubeFaceSize}, 1);
    pc.sun = iblSun_;
    const ResourceHandle sv = skyViewHandle_;
    auto p = g.addPass("atmosphere_ibl", PassKind::Device,
                       [this, sv, pc, firstStep, lastStep, index = back_](PassContext& ctx) {
                           for (uint32_t s = firstStep; s <= lastStep; ++s)
                               recordIblStep(ctx.cmd(), s, ctx.image(sv), pc, index);
                       });
    p.read(skyViewHandle_, Use::Sampled);
    p.sideEffect();
    lastIblStep_ = lastStep;
    if (lastStep == 3) {
        front_ = cube.environment;
        back_ ^= 1u;
        step_ = 0;
    } else {
        step_ = lastStep + 1;
    }
}

void AtmospherePass::recordIblStep(VkCommandBuffer cmd, uint32_t step, const ImageRef& skyView,
                                   const Push& pc, uint32_t index) const {
    const Cube& c = cubes_[index];
    const GpuImage& cube = c.environment->cube();
    const GpuImage& prefiltered = c.environment->prefiltered();
    if (step == 1) {
        // The frames that lit with this environment before may still be reading it (in
        // submission order): wait for every earlier command, then discard it.
        for (const GpuImage* image : {&cube, &prefiltered}) {
            transitionImage(cmd, *image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                            VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 0,
                            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        }
        VkDescriptorImageInfo in{linear_.handle(), skyView.view(),
                                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
        VkDescriptorImageInfo out{VK_NULL_HANDLE, c.views->cubeWrite[0].handle(),
                                  VK_IMAGE_LAYOUT_GENERAL};
        VkWriteDescriptorSet writes[] = {sampledImageWrite(ATMOSPHERE_BINDING_SKY_VIEW, &in),
                                         storageImageWrite(ATMOSPHERE_BINDING_DESTINATION, &out)};
        cubePipeline_.bind(cmd);
        cubePipeline_.pushDescriptors(cmd, writes);
        cubePipeline_.pushConstants(cmd, &pc, sizeof(pc));
        const uint32_t face = cube.desc().width;
        vkCmdDispatch(cmd, groups(face), groups(face), 6);
        filter_.recordMips(cmd, cube, *c.views);
    } else if (step == 2) {
        filter_.recordPrefilter(cmd, cube, prefiltered, *c.views);
    } else {
        filter_.recordIrradiance(cmd, cube, c.environment->irradianceSh());
        EnvironmentFilter::finish(cmd, cube, prefiltered);
    }
}

ResourceHandle AtmospherePass::declareBackground(FrameGraph& g, ResourceHandle camera,
                                                 ResourceHandle depth, ResourceHandle hdr,
                                                 const GpuBuffer& cameraBuffer) {
    const Push pb = push({1u, 1u}, 1);
    const ResourceHandle t = transmittanceHandle_, sv = skyViewHandle_;
    auto p = g.addPass(
        "atmosphere_sky", PassKind::Device,
        [this, t, sv, depth, hdr, pb, &cameraBuffer](PassContext& ctx) {
            const ImageRef target = ctx.image(hdr);
            VkDescriptorBufferInfo cameraInfo{cameraBuffer.handle(), 0, VK_WHOLE_SIZE};
            VkDescriptorImageInfo tIn{linear_.handle(), ctx.image(t).view(),
                                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
            VkDescriptorImageInfo svIn{linear_.handle(), ctx.image(sv).view(),
                                       VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
            VkDescriptorImageInfo depthIn{nearest_.handle(), ctx.image(depth).view(),
                                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
            VkDescriptorImageInfo out{VK_NULL_HANDLE, target.view(), VK_IMAGE_LAYOUT_GENERAL};
            VkWriteDescriptorSet writes[] = {
                uniformBufferWrite(CAMERA_BINDING, &cameraInfo),
                sampledImageWrite(ATMOSPHERE_BINDING_TRANSMITTANCE, &tIn),
                sampledImageWrite(ATMOSPHERE_BINDING_SKY_VIEW, &svIn),
                sampledImageWrite(ATMOSPHERE_BINDING_DEPTH, &depthIn),
                storageImageWrite(ATMOSPHERE_BINDING_HDR, &out)};
            backgroundPipeline_.bind(ctx.cmd());
            backgroundPipeline_.pushDescriptors(ctx.cmd(), writes);
            backgroundPipeline_.pushConstants(ctx.cmd(), &pb, sizeof(pb));
            vkCmdDispatch(ctx.cmd(), groups(target.desc().width), groups(target.desc().height), 1);
        });
    p.read(camera, Use::Uniform);
    p.read(depth, Use::Sampled);
    p.read(transmittanceHandle_, Use::Sampled);
    p.read(skyViewHandle_, Use::Sampled);
    return p.write(hdr, Use::StorageReadWrite);
}

}  // namespace candela::render
