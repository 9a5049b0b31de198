#pragma once
// The device work that turns an environment cube's first mip into what the lighting pass
// samples, in three steps a caller may record in one command buffer (an EXR sky, once) or
// spread over frames (the atmosphere's sky, updated as the sun moves):
//   mips: the cube's mip chain (2x2 averages);
//   prefilter: the GGX-prefiltered cube, one roughness per mip (filtered importance sampling);
//   irradiance: order-2 SH irradiance, projected from a 32x32 mip.
// Every step expects the images in GENERAL and leaves them so; finish() makes them
// SHADER_READ_ONLY_OPTIMAL for whatever reads them next.
#include <vulkan/vulkan.h>

#include <vector>

#include "candela/render/pipeline.h"
#include "vk/image_view.h"
#include "vk/sampler.h"

namespace candela::render {

class Environment;
class GpuBuffer;
class GpuContext;
class GpuImage;

// The per-mip views of one environment's cubes, made once per environment.
struct EnvironmentViews {
    EnvironmentViews(GpuContext& context, const GpuImage& cube, const GpuImage& prefiltered);
    std::vector<ImageView> cubeWrite;  // 2D array, one per mip
    std::vector<ImageView> cubeRead;   // cube, one per mip
    std::vector<ImageView> prefilteredWrite;
};

class EnvironmentFilter {
public:
    explicit EnvironmentFilter(GpuContext& context);

    void recordMips(VkCommandBuffer cmd, const GpuImage& cube, const EnvironmentViews& views) const;
    void recordPrefilter(VkCommandBuffer cmd, const GpuImage& cube, const GpuImage& prefiltered,
                         const EnvironmentViews& views) const;
    void recordIrradiance(VkCommandBuffer cmd, const GpuImage& cube,
                          const GpuBuffer& irradianceSh) const;
    // GENERAL -> SHADER_READ_ONLY_OPTIMAL for both cubes, and the SH writes made visible to
    // every later command.
    static void finish(VkCommandBuffer cmd, const GpuImage& cube, const GpuImage& prefiltered);

private:
    Sampler linear_;
    Sampler trilinear_;
    Pipeline downsample_;
    Pipeline prefilter_;
    Pipeline projectSh_;
};

// A barrier between two dispatches on `image` in GENERAL: the next samples what this wrote.
void environmentWriteBarrier(VkCommandBuffer cmd, const GpuImage& image);

}  // namespace candela::render
