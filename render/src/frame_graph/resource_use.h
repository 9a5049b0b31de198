#pragma once
// How a pass uses an image or a buffer, and what that means for synchronization: the pipeline
// stages and access bits of the use, the image layout it needs, and whether it writes.
// The frame graph derives every barrier from these; no pass records one itself.
#include <vulkan/vulkan.h>

#include <cstdint>

namespace candela::render {

enum class Use : uint8_t {
    Sampled,           // read through a sampler
    StorageRead,       // storage image or buffer, read
    StorageWrite,      // storage image or buffer, written (previous contents not read)
    StorageReadWrite,  // read and written (atomics, read-modify-write)
    Uniform,           // uniform buffer
    ColorAttachment,   // colour target (cleared or loaded, then stored)
    DepthWrite,        // depth target, tested and written
    DepthRead,         // depth target, tested only
    TransferSrc,
    TransferDst,  // copies and fills
    HostRead,     // read back on the CPU after the frame's first submission
    HostWrite,    // written by the CPU (a host pass) before a later device pass reads it
    VertexInput,  // vertex buffer read by a draw's input assembly (deformed vertices)
};

// Shader stages a Sampled/Storage/Uniform use happens in; ignored by the other uses.
inline constexpr VkPipelineStageFlags2 kComputeStage = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
inline constexpr VkPipelineStageFlags2 kFragmentStage = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
inline constexpr VkPipelineStageFlags2 kVertexStage = VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT;
// A draw's shaders: uniforms both the vertex and fragment stages read.
inline constexpr VkPipelineStageFlags2 kRasterStages = kVertexStage | kFragmentStage;

struct UseInfo {
    VkPipelineStageFlags2 stages = 0;
    VkAccessFlags2 access = 0;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;  // images only
    bool writes = false;
    bool reads = false;
};

// `shaderStages` applies to shader uses. Depth images read by shaders use
// SHADER_READ_ONLY_OPTIMAL like colour images.
UseInfo useInfo(Use use, VkPipelineStageFlags2 shaderStages);
const char* useName(Use use);

}  // namespace candela::render
