#include "frame_graph/resource_use.h"

namespace candela::render {

UseInfo useInfo(Use use, VkPipelineStageFlags2 shaderStages) {
    constexpr VkPipelineStageFlags2 kDepthTests =
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    switch (use) {
        case Use::Sampled:
            // SHADER_READ (not SAMPLED_READ): what best practices expects for the layout.
            return {shaderStages, VK_ACCESS_2_SHADER_READ_BIT,
                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, false, true};
        case Use::StorageRead:
            return {shaderStages, VK_ACCESS_2_SHADER_STORAGE_READ_BIT, VK_IMAGE_LAYOUT_GENERAL,
                    false, true};
        case Use::StorageWrite:
            return {shaderStages, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_IMAGE_LAYOUT_GENERAL,
                    true, false};
        case Use::StorageReadWrite:
            return {shaderStages,
                    VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                    VK_IMAGE_LAYOUT_GENERAL, true, true};
        case Use::Uniform:
            return {shaderStages, VK_ACCESS_2_UNIFORM_READ_BIT, VK_IMAGE_LAYOUT_UNDEFINED, false,
                    true};
        case Use::ColorAttachment:
            return {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                    VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, true, true};
        case Use::DepthWrite:
            return {kDepthTests,
                    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                        VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                    VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, true, true};
        case Use::DepthRead:
            return {kDepthTests, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
                    VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, false, true};
        case Use::TransferSrc:
            return {VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                    VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, false, true};
        case Use::TransferDst:
            return {VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                    VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, true, false};
        case Use::HostRead:
            return {VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT,
                    VK_IMAGE_LAYOUT_GENERAL, false, true};
        case Use::HostWrite:
            return {VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_WRITE_BIT,
                    VK_IMAGE_LAYOUT_GENERAL, true, false};
        case Use::VertexInput:
            return {VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT,
                    VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT, VK_IMAGE_LAYOUT_UNDEFINED, false, true};
    }
    return {};
}

const char* useName(Use use) {
    switch (use) {
        case Use::Sampled:
            return "sampled";
        case Use::StorageRead:
            return "storage read";
        case Use::StorageWrite:
            return "storage write";
        case Use::StorageReadWrite:
            return "storage read-write";
        case Use::Uniform:
            return "uniform";
        case Use::ColorAttachment:
            return "colour attachment";
        case Use::DepthWrite:
            return "depth write";
        case Use::DepthRead:
            return "depth read";
        case Use::TransferSrc:
            return "transfer src";
        case Use::TransferDst:
            return "transfer dst";
        case Use::HostRead:
            return "host read";
        case Use::HostWrite:
            return "host write";
        case Use::VertexInput:
            return "vertex input";
    }
    return "?";
}

}  // namespace candela::render
