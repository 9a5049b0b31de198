#include "passes/lighting/lighting_pass.h"

#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_context.h"
#include "clustered/gpu_cluster_params.h"
#include "common/specialization_ids.h"
#include "gbuffer_targets.h"
#include "ibl/environment_descriptors.h"
#include "shaders/lighting.comp.spv.h"

namespace candela::render {

namespace {
struct Push {
    GpuClusterParams grid;
    uint32_t directionalCount;
    float skyIntensity;
    float prefilteredMipCount;
    uint32_t referenceSamples;
};

// Values of kIblMode in lighting.comp.
uint32_t iblModeConstant(const std::optional<IblMode>& mode) {
    if (!mode) return 0;
    switch (*mode) {
        case IblMode::SplitSum:
            return 1;
        case IblMode::Mobile:
            return 2;
        case IblMode::Reference:
            return 3;
    }
    return 0;
}
}  // namespace

std::vector<std::string> LightingFeatures::names() const {
    std::vector<std::string> out = {"shading_default_lit", "lights_point"};
    if (subsurface) out.push_back("shading_subsurface");
    if (legacyDiffuseSpecular) out.push_back("shading_legacy_diffuse_specular");
    if (sphereLights) out.push_back("lights_sphere");
    if (tubeLights) out.push_back("lights_tube");
    if (spotLights) out.push_back("lights_spot");
    out.push_back(clustered ? "light_culling_clustered" : "light_culling_brute_force");
    if (countLightPairs) out.push_back("light_pair_counters");
    if (ibl) out.push_back(std::string("ibl_") + iblModeName(*ibl));
    out.push_back(brdf == BrdfModel::Ue4 ? "brdf_ue4" : "brdf_energy_conserving");
    return out;
}

void setShadingConstants(SpecializationConstants& constants, const LightingFeatures& features) {
    constants.set(SPEC_SUBSURFACE_ENABLED, features.subsurface);
    constants.set(SPEC_LEGACY_DIFFUSE_SPECULAR_ENABLED, features.legacyDiffuseSpecular);
    constants.set(SPEC_SPHERE_LIGHTS_ENABLED, features.sphereLights);
    constants.set(SPEC_TUBE_LIGHTS_ENABLED, features.tubeLights);
    constants.set(SPEC_SPOT_LIGHTS_ENABLED, features.spotLights);
    constants.set(SPEC_CLUSTERED, features.clustered);
    constants.set(SPEC_ENERGY_CONSERVING, features.brdf == BrdfModel::EnergyConserving);
}

LightingPass::LightingPass(GpuContext& context)
    : context_(context), pointSampler_(context, SamplerDesc{VK_FILTER_NEAREST}) {
    setFeatures({});
}

LightingPass::~LightingPass() = default;

void LightingPass::setFeatures(const LightingFeatures& features) {
    if (built_ && features == features_) return;
    features_ = features;
    SpecializationConstants constants;
    setShadingConstants(constants, features);
    constants.set(SPEC_COUNT_LIGHT_PAIRS, features.countLightPairs);
    constants.set(SPEC_IBL_MODE, iblModeConstant(features.ibl));
    const DescriptorBinding bindings[] = {
        {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
        {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
        {2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_COMPUTE_BIT},
        {3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_COMPUTE_BIT},
        {4, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_COMPUTE_BIT},
        {5, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_COMPUTE_BIT},
        {6, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_COMPUTE_BIT},
        {7, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT},
        {8, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
        {9, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
        {10, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
        {11, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
        {12, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_COMPUTE_BIT},
        {13, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_COMPUTE_BIT},
        {14, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_COMPUTE_BIT},
        {15, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
        {16, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    };
    pipeline_ = Pipeline::compute(context_, lighting_comp_spv, bindings, sizeof(Push), &constants);
    built_ = true;
}

uint32_t LightingPass::workgroupCount(uint32_t width, uint32_t height) {
    return ((width + 7) / 8) * ((height + 7) / 8);
}

void LightingPass::record(VkCommandBuffer cmd, const Inputs& in) const {
    VkDescriptorBufferInfo cameraInfo{in.camera->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo lightInfo{in.lights->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo rangesInfo{in.clusterRanges->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo indicesInfo{in.lightIndices->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo countsInfo{in.pairCounts->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo depthRangeInfo{in.depthRange->handle(), 0, VK_WHOLE_SIZE};
    std::array<VkDescriptorImageInfo, 5> images{};
    for (size_t i = 0; i < 4; ++i) {
        images[i] = {pointSampler_.handle(), in.gbuffer->color[i].view(),
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    }
    images[4] = {pointSampler_.handle(), in.gbuffer->depth.view(),
                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo hdrInfo{VK_NULL_HANDLE, in.hdr.view(), VK_IMAGE_LAYOUT_GENERAL};
    const EnvironmentDescriptors& env = *in.environment;
    const VkWriteDescriptorSet writes[] = {
        uniformBufferWrite(0, &cameraInfo),         storageBufferWrite(1, &lightInfo),
        sampledImageWrite(2, &images[0]),           sampledImageWrite(3, &images[1]),
        sampledImageWrite(4, &images[2]),           sampledImageWrite(5, &images[3]),
        sampledImageWrite(6, &images[4]),           storageImageWrite(7, &hdrInfo),
        storageBufferWrite(8, &rangesInfo),         storageBufferWrite(9, &indicesInfo),
        storageBufferWrite(10, &countsInfo),        storageBufferWrite(11, &depthRangeInfo),
        sampledImageWrite(12, &env.environment),    sampledImageWrite(13, &env.prefiltered),
        sampledImageWrite(14, &env.brdfLut),        storageBufferWrite(15, &env.irradianceSh),
        storageBufferWrite(16, &env.samplingTable),
    };
    Push push{toGpu(*in.grid), in.directionalCount, in.skyIntensity, env.prefilteredMipCount,
              in.referenceSamples};
    pipeline_.bind(cmd);
    pipeline_.pushDescriptors(cmd, writes);
    pipeline_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, (in.hdr.desc().width + 7) / 8, (in.hdr.desc().height + 7) / 8, 1);
}

}  // namespace candela::render
