#include "ibl/environment_precompute.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <vector>

#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_context.h"
#include "candela/render/gpu_image.h"
#include "candela/render/pipeline.h"
#include "ibl/environment_filter.h"
#include "ibl/ibl_bindings.h"
#include "shaders/cube_resample.comp.spv.h"
#include "shaders/latlong_to_cube.comp.spv.h"
#include "vk/image_view.h"
#include "vk/memory_barrier.h"
#include "vk/sampler.h"

namespace candela::render {

namespace {

// fp16 holds 65504: brighter texels (the sun's disc) are clamped there rather than becoming Inf.
constexpr float kMaxRadiance = 65000.0f;

const DescriptorBinding kSampleAndWrite[] = {
    {IBL_BINDING_SOURCE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_COMPUTE_BIT},
    {IBL_BINDING_DESTINATION, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT},
};

uint32_t groups(uint32_t size) {
    return (size + 7) / 8;
}

// Source texels as RGBA32F in an image the resample shader samples.
GpuImage uploadSource(GpuContext& context, const content::EnvironmentMap& map) {
    bool cube = map.layout == content::EnvironmentLayout::Cube;
    const content::FloatImage& first = cube ? map.cubeFaces[0] : map.latLong;
    GpuImage image(context, {VK_FORMAT_R32G32B32A32_SFLOAT, first.width, first.height, 1, cube,
                             VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT});
    VkDeviceSize layerBytes = VkDeviceSize(first.width) * first.height * 16;
    GpuBuffer staging(context, layerBytes * image.layers(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                      MemoryLocation::HostVisible);
    for (uint32_t layer = 0; layer < image.layers(); ++layer) {
        const content::FloatImage& face = cube ? map.cubeFaces[layer] : map.latLong;
        std::memcpy(static_cast<char*>(staging.mapped()) + layer * layerBytes, face.rgba.data(),
                    layerBytes);
    }
    context.submitAndWait([&](VkCommandBuffer cmd) {
        transitionImage(cmd, image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                        VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, image.layers()};
        region.imageExtent = {first.width, first.height, 1};
        vkCmdCopyBufferToImage(cmd, staging.handle(), image.handle(),
                               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        transitionImage(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_READ_BIT);
    });
    return image;
}

}  // namespace

uint32_t sourceCubeFaceSize(const content::EnvironmentMap& map) {
    if (map.layout == content::EnvironmentLayout::Cube) return map.cubeFaces[0].width;
    return std::max(map.latLong.width / 4, 1u);  // a face spans a quarter of the longitudes
}

EnvironmentSizes environmentSizesFor(uint32_t sourceFace) {
    EnvironmentSizes s;
    s.cubeFaceSize = std::clamp(std::bit_ceil(std::max(sourceFace, 1u)), 16u, 512u);
    s.cubeMipCount = uint32_t(std::bit_width(s.cubeFaceSize));
    s.prefilteredFaceSize = std::min(s.cubeFaceSize, 256u);
    s.prefilteredMipCount = uint32_t(std::bit_width(s.prefilteredFaceSize)) - 2;  // down to 4x4
    return s;
}

void precomputeEnvironment(GpuContext& context, const content::EnvironmentMap& map,
                           const GpuImage& cube, const GpuImage& prefiltered,
                           const GpuBuffer& irradianceSh) {
    bool cubeSource = map.layout == content::EnvironmentLayout::Cube;
    GpuImage source = uploadSource(context, map);
    Sampler sourceSampler(context, {VK_FILTER_LINEAR, false,
                                    cubeSource ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE
                                               : VK_SAMPLER_ADDRESS_MODE_REPEAT,
                                    VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE});
    Pipeline resample =
        Pipeline::compute(context,
                          cubeSource ? std::span<const uint32_t>(cube_resample_comp_spv)
                                     : std::span<const uint32_t>(latlong_to_cube_comp_spv),
                          kSampleAndWrite, 8);
    const EnvironmentFilter filter(context);
    const EnvironmentViews views(context, cube, prefiltered);
    const uint32_t cubeFace = cube.desc().width;

    context.submitAndWait([&](VkCommandBuffer cmd) {
        for (const GpuImage* image : {&cube, &prefiltered}) {
            transitionImage(cmd, *image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                            VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        }
        VkDescriptorImageInfo in{sourceSampler.handle(), source.view(),
                                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
        VkDescriptorImageInfo out{VK_NULL_HANDLE, views.cubeWrite[0].handle(),
                                  VK_IMAGE_LAYOUT_GENERAL};
        VkWriteDescriptorSet writes[] = {sampledImageWrite(IBL_BINDING_SOURCE, &in),
                                         storageImageWrite(IBL_BINDING_DESTINATION, &out)};
        struct {
            uint32_t faceSize;
            float maxRadiance;
        } resamplePush{cubeFace, kMaxRadiance};
        resample.bind(cmd);
        resample.pushDescriptors(cmd, writes);
        resample.pushConstants(cmd, &resamplePush, sizeof(resamplePush));
        vkCmdDispatch(cmd, groups(cubeFace), groups(cubeFace), 6);
        filter.recordMips(cmd, cube, views);
        filter.recordPrefilter(cmd, cube, prefiltered, views);
        filter.recordIrradiance(cmd, cube, irradianceSh);
        EnvironmentFilter::finish(cmd, cube, prefiltered);
    });
}

}  // namespace candela::render
