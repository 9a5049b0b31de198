#version 460
#extension GL_GOOGLE_include_directive : require
#include "exposure_bindings.h"
// Luminance histogram of the HDR target in EV100 (EV100 = log2(L * 100 / 12.5), the reflected
// light meter's calibration, K = 12.5) over a quarter of the pixels: each workgroup counts into shared memory, then adds its
// bins to the frame's histogram, which the CPU reads back to meter the next frame's exposure.

layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = EXPOSURE_BINDING_HDR, rgba32f) uniform readonly image2D hdr;
layout(std430, binding = EXPOSURE_BINDING_HISTOGRAM) buffer Histogram {
    uint bins[HISTOGRAM_BINS];
};

shared uint localBins[HISTOGRAM_BINS];

void main() {
    uint local = gl_LocalInvocationIndex;
    if (local < HISTOGRAM_BINS) localBins[local] = 0u;
    barrier();
    // Every other pixel in each direction: a meter needs the distribution, not every pixel,
    // and on a CPU device the shared-memory atomics are this pass's whole cost.
    ivec2 pixel = 2 * ivec2(gl_GlobalInvocationID.xy);
    if (all(lessThan(pixel, imageSize(hdr)))) {
        float luminance = dot(imageLoad(hdr, pixel).rgb, vec3(0.2126, 0.7152, 0.0722));
        if (luminance > 0.0) {
            float ev100 = log2(luminance * 100.0 / 12.5);
            float bin = floor((ev100 - HISTOGRAM_MIN_EV100) * HISTOGRAM_BINS_PER_EV);
            if (bin >= 0.0) atomicAdd(localBins[uint(min(bin, float(HISTOGRAM_BINS - 1)))], 1u);
        }
    }
    barrier();
    if (local < HISTOGRAM_BINS && localBins[local] > 0u) atomicAdd(bins[local], localBins[local]);
}
