#include "passes/exposure/exposure_pass.h"

#include "candela/render/gpu_image.h"
#include "passes/exposure/exposure_bindings.h"
#include "shaders/luminance_histogram.comp.spv.h"

namespace candela::render {

ExposureHistogramPass::ExposureHistogramPass(GpuContext& context) {
    const DescriptorBinding bindings[] = {
        {EXPOSURE_BINDING_HDR, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT},
        {EXPOSURE_BINDING_HISTOGRAM, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_COMPUTE_BIT},
    };
    pipeline_ = Pipeline::compute(context, luminance_histogram_comp_spv, bindings, 0);
}

void ExposureHistogramPass::record(VkCommandBuffer cmd, const ImageRef& hdr,
                                   const BufferRef& histogram) const {
    VkDescriptorImageInfo hdrInfo{VK_NULL_HANDLE, hdr.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorBufferInfo histogramInfo{histogram.handle(), 0, VK_WHOLE_SIZE};
    const VkWriteDescriptorSet writes[] = {
        storageImageWrite(EXPOSURE_BINDING_HDR, &hdrInfo),
        storageBufferWrite(EXPOSURE_BINDING_HISTOGRAM, &histogramInfo)};
    pipeline_.bind(cmd);
    pipeline_.pushDescriptors(cmd, writes);
    // One invocation per 2x2 pixels (luminance_histogram.comp).
    vkCmdDispatch(cmd, (hdr.desc().width + 31) / 32, (hdr.desc().height + 31) / 32, 1);
}

}  // namespace candela::render
