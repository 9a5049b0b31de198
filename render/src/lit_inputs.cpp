#include "lit_inputs.h"

#include "candela/render/gpu_buffer.h"
#include "common/lit_bindings.h"

namespace candela::render {

void LitInputHandles::declareReads(FrameGraph::PassBuilder& pass,
                                   VkPipelineStageFlags2 stages) const {
    pass.read(lights, Use::StorageRead, stages);
    if (clustered) {
        pass.read(clusters.ranges, Use::StorageRead, stages);
        pass.read(clusters.indices, Use::StorageRead, stages);
        pass.read(clusters.depthRange, Use::StorageRead, stages);
    }
    if (shadows) {
        pass.read(shadowAtlas, Use::Sampled, stages);
        pass.read(shadowViews, Use::StorageRead, stages);
        pass.read(shadowLights, Use::StorageRead, stages);
    }
    if (skyOcclusion) pass.read(skyOcclusionAtlas, Use::Sampled, stages);
}

std::vector<DescriptorBinding> withLitInputBindings(std::span<const DescriptorBinding> own,
                                                    VkShaderStageFlags stages) {
    constexpr VkDescriptorType kBuffer = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    constexpr VkDescriptorType kImage = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    std::vector<DescriptorBinding> bindings(own.begin(), own.end());
    for (const auto& [binding, type] : std::initializer_list<std::pair<uint32_t, VkDescriptorType>>{
             {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
             {LIGHT_BUFFER_BINDING, kBuffer},
             {LIT_BINDING_CLUSTER_RANGES, kBuffer},
             {LIT_BINDING_LIGHT_INDICES, kBuffer},
             {LIT_BINDING_DEPTH_RANGE, kBuffer},
             {LIT_BINDING_PREFILTERED, kImage},
             {LIT_BINDING_BRDF_LUT, kImage},
             {LIT_BINDING_IRRADIANCE_SH, kBuffer},
             {LIT_BINDING_SHADOW_ATLAS, kImage},
             {LIT_BINDING_SHADOW_VIEWS, kBuffer},
             {LIT_BINDING_SHADOW_LIGHTS, kBuffer},
             {LIT_BINDING_SHADOW_ATLAS_COMPARE, kImage},
             {LIT_BINDING_LTC_MATRIX, kImage},
             {LIT_BINDING_LTC_MAGNITUDE, kImage},
             {LIT_BINDING_AREA_LIGHT_TEXTURES, kImage},
             {LIT_BINDING_SKY_OCCLUSION, kImage}}) {
        bindings.push_back({binding, type, stages});
    }
    return bindings;
}

LitDescriptorWrites::LitDescriptorWrites(const LitInputs& in,
                                         std::span<const VkWriteDescriptorSet> own)
    : buffers_{{{in.camera->handle(), 0, VK_WHOLE_SIZE},
                {in.lights->handle(), 0, VK_WHOLE_SIZE},
                {in.clusters->ranges().handle(), 0, VK_WHOLE_SIZE},
                {in.clusters->indices().handle(), 0, VK_WHOLE_SIZE},
                {in.clusters->depthRange().handle(), 0, VK_WHOLE_SIZE}}},
      writes_(own.begin(), own.end()) {
    const EnvironmentDescriptors& env = in.environment;
    const ShadowDescriptors& shadows = in.shadows;
    writes_.insert(writes_.end(),
                   {uniformBufferWrite(CAMERA_BINDING, &buffers_[0]),
                    storageBufferWrite(LIGHT_BUFFER_BINDING, &buffers_[1]),
                    storageBufferWrite(LIT_BINDING_CLUSTER_RANGES, &buffers_[2]),
                    storageBufferWrite(LIT_BINDING_LIGHT_INDICES, &buffers_[3]),
                    storageBufferWrite(LIT_BINDING_DEPTH_RANGE, &buffers_[4]),
                    sampledImageWrite(LIT_BINDING_PREFILTERED, &env.prefiltered),
                    sampledImageWrite(LIT_BINDING_BRDF_LUT, &env.brdfLut),
                    storageBufferWrite(LIT_BINDING_IRRADIANCE_SH, &env.irradianceSh),
                    sampledImageWrite(LIT_BINDING_SHADOW_ATLAS, &shadows.atlas),
                    storageBufferWrite(LIT_BINDING_SHADOW_VIEWS, &shadows.views),
                    storageBufferWrite(LIT_BINDING_SHADOW_LIGHTS, &shadows.lights),
                    sampledImageWrite(LIT_BINDING_SHADOW_ATLAS_COMPARE, &shadows.atlasCompare),
                    sampledImageWrite(LIT_BINDING_LTC_MATRIX, &env.ltcMatrix),
                    sampledImageWrite(LIT_BINDING_LTC_MAGNITUDE, &env.ltcMagnitude),
                    sampledImageWrite(LIT_BINDING_AREA_LIGHT_TEXTURES, &env.areaLightTextures),
                    sampledImageWrite(LIT_BINDING_SKY_OCCLUSION, &in.skyOcclusion)});
}

}  // namespace candela::render
