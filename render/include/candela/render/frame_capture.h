#pragma once
// Reads the frame's targets back to the CPU and writes them as EXR (scene radiance) or PNG.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "candela/render/gpu_buffer.h"

namespace candela::render {

class GpuContext;
class Renderer;

struct CapturedFrame {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<float> hdrRgb;     // linear scene radiance in cd/m^2, before exposure
    std::vector<uint8_t> ldrRgba;  // final tonemapped sRGB pixels

    size_t nonFiniteHdrValues() const;  // every capture is checked for NaN/Inf
};

class FrameReadback {
public:
    FrameReadback(GpuContext& context, uint32_t width, uint32_t height);
    // Records copies of both targets; they must be in TRANSFER_SRC_OPTIMAL (recordFrame's end).
    void recordCopy(VkCommandBuffer cmd, const Renderer& renderer) const;
    // Valid once the submission holding recordCopy has completed.
    CapturedFrame read() const;

private:
    uint32_t width_;
    uint32_t height_;
    GpuBuffer hdrStaging_;
    GpuBuffer ldrStaging_;
};

// Returns an empty string on success, otherwise a message naming the file and the problem.
std::string writeCapture(const std::filesystem::path& path, const CapturedFrame& frame);

}  // namespace candela::render
