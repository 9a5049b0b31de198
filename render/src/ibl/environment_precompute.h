#pragma once
// The device work that turns an HDR environment into what the lighting pass samples:
//   source (lat-long or six faces) -> environment cube mip 0 -> its mip chain (2x2 averages)
//   -> GGX-prefiltered cube, one roughness per mip (filtered importance sampling)
//   -> order-2 SH irradiance, projected from a 32x32 mip.
#include <cstdint>

#include "candela/content/environment_map.h"

namespace candela::render {

class GpuBuffer;
class GpuContext;
class GpuImage;

struct EnvironmentSizes {
    uint32_t cubeFaceSize;
    uint32_t cubeMipCount;
    uint32_t prefilteredFaceSize;
    uint32_t prefilteredMipCount;  // roughness m / (count - 1) at mip m
};

// Cube faces about as detailed as the source (a 2k lat-long gives 512), at most 512;
// prefiltered cube at most 256, down to 4x4 at roughness 1.
EnvironmentSizes environmentSizesFor(uint32_t sourceCubeFaceSize);
uint32_t sourceCubeFaceSize(const content::EnvironmentMap& map);

// GGX samples per prefiltered texel: enough with filtered importance sampling (Karis 2013, "Real
// Shading in Unreal Engine 4", notes that 64 is what UE4 settled on).
constexpr uint32_t kPrefilterSampleCount = 64;

// Fills `cube` (all mips), `prefiltered` (all mips) and `irradianceSh` (9 vec4) from `map`;
// both images end in SHADER_READ_ONLY_OPTIMAL.
void precomputeEnvironment(GpuContext& context, const content::EnvironmentMap& map,
                           const GpuImage& cube, const GpuImage& prefiltered,
                           const GpuBuffer& irradianceSh);

}  // namespace candela::render
