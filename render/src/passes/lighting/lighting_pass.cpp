#include "passes/lighting/lighting_pass.h"

#include <algorithm>

#include "candela/content/render_setting_table.h"
#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_context.h"
#include "clustered/gpu_cluster_params.h"
#include "common/specialization_ids.h"
#include "gbuffer_targets.h"
#include "ibl/environment_descriptors.h"
#include "lights/gpu_light_types.h"
#include "passes/lighting/lighting_bindings.h"
#include "shaders/lighting.comp.spv.h"

namespace candela::render {

namespace {
struct Push {
    GpuClusterParams grid;
    uint32_t directionalCount;
    float skyIntensity;
    float prefilteredMipCount;
    uint32_t referenceSamples;
    float aoIntensity;
    uint32_t aoMultiBounce;
    uint32_t lightFirst;  // the brute-force dispatch's lights: [lightFirst, lightEnd)
    uint32_t lightEnd;
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
    if ((sphereLights || tubeLights) && areaLights == AreaLightMode::Ltc) {
        out.push_back("area_lights_ltc");
    }
    for (const GpuLightTypeInfo& t : kGpuLightTypeTable) {
        if (t.feature && (lightTypes & bit(t.type))) out.push_back(t.feature);
    }
    out.push_back(clustered ? "light_culling_clustered" : "light_culling_brute_force");
    for (const LightLoopName& loop : kLightLoopNames) {
        if (lightLoops & loop.bit) out.push_back(std::string("light_loop_") + loop.name);
    }
    if (countLightPairs) out.push_back("light_pair_counters");
    if (shadows) out.push_back("shadows");
    if (skyOcclusion) out.push_back("sky_occlusion");
    if (ibl) out.push_back(std::string("ibl_") + iblModeName(*ibl));
    out.push_back(brdf == BrdfModel::Ue4 ? "brdf_ue4" : "brdf_energy_conserving");
    if (anisotropy) out.push_back("material_anisotropy");
    if (clearCoat) out.push_back("material_clear_coat");
    if (ao != AoMode::Off) out.push_back("ao_" + content::renderSettingName(ao));
    return out;
}

void setShadingConstants(SpecializationConstants& constants, const LightingFeatures& features) {
    constants.set(SPEC_SUBSURFACE_ENABLED, features.subsurface);
    constants.set(SPEC_LEGACY_DIFFUSE_SPECULAR_ENABLED, features.legacyDiffuseSpecular);
    constants.set(SPEC_SPHERE_LIGHTS_ENABLED, features.sphereLights);
    constants.set(SPEC_TUBE_LIGHTS_ENABLED, features.tubeLights);
    constants.set(SPEC_LIGHT_LOOPS, features.lightLoops);
    for (const GpuLightTypeInfo& t : kGpuLightTypeTable) {
        if (t.specialization != kNoSpecialization) {
            constants.set(t.specialization,
                          (features.lightTypes & LightingFeatures::bit(t.type)) != 0);
        }
    }
    constants.set(SPEC_CLUSTERED, features.clustered);
    constants.set(SPEC_SHADOWS_ENABLED, features.shadows);
    constants.set(SPEC_DIRECTIONAL_SHADOWS, features.directionalShadows);
    constants.set(SPEC_LOCAL_SHADOWS, features.localShadows);
    constants.set(SPEC_SOFT_SHADOWS, features.softShadows);
    constants.set(SPEC_HARD_SHADOW_TAPS, int32_t(features.hardShadowTapsPerAxis));
    constants.set(SPEC_ENERGY_CONSERVING, features.brdf == BrdfModel::EnergyConserving);
    constants.set(SPEC_AREA_LIGHTS_LTC, features.areaLights == AreaLightMode::Ltc);
    constants.set(SPEC_AREA_LIGHT_PATHS, features.areaLightPaths);
    constants.set(SPEC_AREA_TEXTURE_CELLS, features.areaTextureCells);
}

void setMaterialExtensionConstants(SpecializationConstants& constants,
                                   const LightingFeatures& features) {
    constants.set(SPEC_ANISOTROPY_ENABLED, features.anisotropy);
    constants.set(SPEC_CLEAR_COAT_ENABLED, features.clearCoat);
}

// No pipeline yet: the first setFeatures() compiles the variant the scene needs (the lighting
// shader is the slowest to compile; a default variant would be thrown away).
LightingPass::LightingPass(GpuContext& context)
    : context_(context), pointSampler_(context, SamplerDesc{VK_FILTER_NEAREST}) {}

LightingPass::~LightingPass() = default;

void LightingPass::setFeatures(const LightingFeatures& features) {
    if (built_ && features == features_) return;
    features_ = features;
    SpecializationConstants constants;
    setShadingConstants(constants, features);
    constants.set(SPEC_COUNT_LIGHT_PAIRS, features.countLightPairs);
    constants.set(SPEC_IBL_MODE, iblModeConstant(features.ibl));
    setMaterialExtensionConstants(constants, features);
    // 3: GTAO whose specular occlusion is read from its horizon slice (lighting.comp).
    constants.set(SPEC_AMBIENT_OCCLUSION,
                  features.ao == AoMode::Gtao && features.aoSpecularFromHorizons
                      ? 3u
                      : uint32_t(features.ao));
    constants.set(SPEC_SKY_OCCLUSION, features.skyOcclusion);
    constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;
    constexpr VkDescriptorType kImage = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    constexpr VkDescriptorType kBuffer = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    const DescriptorBinding own[] = {
        {LIGHTING_BINDING_GBUFFER_BASE_COLOR, kImage, kCompute},
        {LIGHTING_BINDING_GBUFFER_NORMAL, kImage, kCompute},
        {LIGHTING_BINDING_GBUFFER_SPECULAR_MODEL, kImage, kCompute},
        {LIGHTING_BINDING_GBUFFER_CUSTOM_DATA, kImage, kCompute},
        {LIGHTING_BINDING_GBUFFER_DEPTH, kImage, kCompute},
        {LIGHTING_BINDING_HDR, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
        {LIGHTING_BINDING_PAIR_COUNTS, kBuffer, kCompute},
        {LIGHTING_BINDING_ENVIRONMENT, kImage, kCompute},
        {LIGHTING_BINDING_SAMPLING_TABLE, kBuffer, kCompute},
        {LIGHTING_BINDING_GBUFFER_ANISOTROPY, kImage, kCompute},
        {LIGHTING_BINDING_GBUFFER_CLEAR_COAT, kImage, kCompute},
        {LIGHTING_BINDING_AMBIENT_OCCLUSION, kImage, kCompute},
        {LIGHTING_BINDING_SPECULAR_OCCLUSION, kImage, kCompute},
    };
    const std::vector<DescriptorBinding> bindings = withLitInputBindings(own, kCompute);
    pipeline_ = Pipeline::compute(context_, lighting_comp_spv, bindings, sizeof(Push), &constants);
    built_ = true;
}

uint32_t LightingPass::workgroupCount(uint32_t width, uint32_t height) {
    return ((width + 7) / 8) * ((height + 7) / 8);
}

void LightingPass::record(VkCommandBuffer cmd, const Inputs& in) const {
    VkDescriptorBufferInfo countsInfo{in.pairCounts->handle(), 0, VK_WHOLE_SIZE};
    std::array<VkDescriptorImageInfo, 7> images{};
    for (size_t i = 0; i < 4; ++i) {
        images[i] = {pointSampler_.handle(), in.gbuffer->color[i].view(),
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    }
    images[4] = {pointSampler_.handle(), in.gbuffer->depth.view(),
                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    // Without the optional targets the variant never reads these bindings; any sampled image
    // keeps the descriptors valid.
    const bool extended = in.gbuffer->extended;
    images[5] = {pointSampler_.handle(),
                 extended ? in.gbuffer->anisotropy.view() : in.gbuffer->color[0].view(),
                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    images[6] = {pointSampler_.handle(),
                 extended ? in.gbuffer->clearCoat.view() : in.gbuffer->color[0].view(),
                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo hdrInfo{VK_NULL_HANDLE, in.hdr.view(), VK_IMAGE_LAYOUT_GENERAL};
    const EnvironmentDescriptors& env = in.lit.environment;
    // Without ambient occlusion the variant never reads these: any 2D image will do, and the
    // LUT (or its placeholder) is always at hand.
    VkDescriptorImageInfo occlusionInfo = env.brdfLut;
    VkDescriptorImageInfo specularOcclusionInfo = env.brdfLut;
    if (in.ambientOcclusion) {
        occlusionInfo = {pointSampler_.handle(), in.ambientOcclusion->view(),
                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    }
    if (in.specularOcclusion) {
        specularOcclusionInfo = {pointSampler_.handle(), in.specularOcclusion->view(),
                                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    }
    const VkWriteDescriptorSet own[] = {
        sampledImageWrite(LIGHTING_BINDING_GBUFFER_BASE_COLOR, &images[0]),
        sampledImageWrite(LIGHTING_BINDING_GBUFFER_NORMAL, &images[1]),
        sampledImageWrite(LIGHTING_BINDING_GBUFFER_SPECULAR_MODEL, &images[2]),
        sampledImageWrite(LIGHTING_BINDING_GBUFFER_CUSTOM_DATA, &images[3]),
        sampledImageWrite(LIGHTING_BINDING_GBUFFER_DEPTH, &images[4]),
        storageImageWrite(LIGHTING_BINDING_HDR, &hdrInfo),
        storageBufferWrite(LIGHTING_BINDING_PAIR_COUNTS, &countsInfo),
        sampledImageWrite(LIGHTING_BINDING_ENVIRONMENT, &env.environment),
        storageBufferWrite(LIGHTING_BINDING_SAMPLING_TABLE, &env.samplingTable),
        sampledImageWrite(LIGHTING_BINDING_GBUFFER_ANISOTROPY, &images[5]),
        sampledImageWrite(LIGHTING_BINDING_GBUFFER_CLEAR_COAT, &images[6]),
        sampledImageWrite(LIGHTING_BINDING_AMBIENT_OCCLUSION, &occlusionInfo),
        sampledImageWrite(LIGHTING_BINDING_SPECULAR_OCCLUSION, &specularOcclusionInfo),
    };
    const LitDescriptorWrites writes(in.lit, own);
    Push push{toGpu(in.lit.clusters->grid()),
              in.lit.clusters->directionalCount(),
              in.lit.skyIntensity,
              env.prefilteredMipCount,
              in.referenceSamples,
              in.aoIntensity,
              in.aoMultiBounce ? 1u : 0u,
              0u,
              in.lightCount};
    pipeline_.bind(cmd);
    pipeline_.pushDescriptors(cmd, writes.writes());
    const uint32_t groupsX = (in.hdr.desc().width + 7) / 8;
    const uint32_t groupsY = (in.hdr.desc().height + 7) / 8;
    if (features_.clustered) {
        pipeline_.pushConstants(cmd, &push, sizeof(push));
        vkCmdDispatch(cmd, groupsX, groupsY, 1);
        return;
    }
    // The brute-force reference adds kBruteForceLightsPerDispatch lights per dispatch, each
    // onto the last one's radiance (and light-pair counts). One dispatch over every light
    // runs unbounded per invocation: a long one trips a GPU's watchdog, and lavapipe stops
    // any invocation's loops after 65,535 iterations in all, which 8,192 area lights pass.
    for (uint32_t first = 0; first == 0 || first < in.lightCount;
         first += kBruteForceLightsPerDispatch) {
        if (first > 0) {
            const VkMemoryBarrier added{VK_STRUCTURE_TYPE_MEMORY_BARRIER, nullptr,
                                        VK_ACCESS_SHADER_WRITE_BIT,
                                        VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT};
            vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                                 VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &added, 0, nullptr, 0,
                                 nullptr);
        }
        push.lightFirst = first;
        push.lightEnd = std::min(in.lightCount, first + kBruteForceLightsPerDispatch);
        pipeline_.pushConstants(cmd, &push, sizeof(push));
        vkCmdDispatch(cmd, groupsX, groupsY, 1);
    }
}

}  // namespace candela::render
