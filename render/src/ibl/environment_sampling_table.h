#pragma once
// Importance sampling of an environment's full-resolution cube by luminance, for the
// reference IBL mode: real skies clip the sun to a few texels of 65504 cd/m^2 carrying a
// large part of the light, which BRDF sampling alone turns into fireflies. The lighting pass
// combines it with BRDF sampling by multiple importance sampling (balance heuristic).
//
// Buffer (std430): uint faceSize, uint texelCount, 2 pads, then per texel vec2(cdf, p): the
// inclusive cumulative probability and the texel's probability, p = L dw / sum(L dw).
#include "candela/render/gpu_buffer.h"

namespace candela::render {

class Environment;
class GpuContext;

class EnvironmentSamplingTable {
public:
    EnvironmentSamplingTable(GpuContext& context, const Environment& environment);

    const Environment* source() const { return source_; }
    const GpuBuffer& buffer() const { return buffer_; }

private:
    const Environment* source_;
    GpuBuffer buffer_;
};

}  // namespace candela::render
