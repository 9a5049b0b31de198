#include "ibl/environment_sampling_table.h"

#include <cmath>
#include <cstring>
#include <glm/gtc/packing.hpp>
#include <vector>

#include "candela/render/environment.h"
#include "candela/render/gpu_context.h"
#include "vk/image_transfer.h"

namespace candela::render {

EnvironmentSamplingTable::EnvironmentSamplingTable(GpuContext& context,
                                                   const Environment& environment)
    : source_(&environment) {
    const uint32_t face = environment.cube().desc().width;
    const size_t texels = size_t(6) * face * face;
    // Mip 0 comes first in the readback: six faces, rows top to bottom, RGBA16F.
    std::vector<uint8_t> bytes =
        readImage(context, environment.cube(), 8, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    std::vector<double> weight(texels);
    double total = 0.0;
    for (size_t i = 0; i < texels; ++i) {
        uint16_t rgb[3];
        std::memcpy(rgb, bytes.data() + i * 8, sizeof(rgb));
        double luminance = 0.2126 * glm::unpackHalf1x16(rgb[0]) +
                           0.7152 * glm::unpackHalf1x16(rgb[1]) +
                           0.0722 * glm::unpackHalf1x16(rgb[2]);
        size_t inFace = i % (size_t(face) * face);
        double u = (double(inFace % face) + 0.5) / face * 2.0 - 1.0;
        double v = (double(inFace / face) + 0.5) / face * 2.0 - 1.0;
        double r2 = 1.0 + u * u + v * v;
        double solidAngle = (4.0 / (double(face) * face)) / (r2 * std::sqrt(r2));
        weight[i] = std::max(luminance, 0.0) * solidAngle;
        total += weight[i];
    }
    buffer_ = GpuBuffer(context, 16 + texels * 8, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                        MemoryLocation::HostVisible);
    auto* header = static_cast<uint32_t*>(buffer_.mapped());
    header[0] = face;
    header[1] = uint32_t(texels);
    header[2] = header[3] = 0;
    auto* table = reinterpret_cast<float*>(header + 4);
    double cumulative = 0.0;
    float previous = 0.0f;
    for (size_t i = 0; i < texels; ++i) {
        // A black sky samples uniformly by solid angle instead of dividing by zero.
        cumulative += total > 0.0 ? weight[i] / total : 1.0 / double(texels);
        float cdf = i + 1 == texels ? 1.0f : float(cumulative);  // the search always lands
        table[2 * i] = cdf;
        // The probability the float search really gives the texel (texels too dim to move a
        // float sum near 1 get none), so the shader's pdf matches what it samples.
        table[2 * i + 1] = cdf - previous;
        previous = cdf;
    }
}

}  // namespace candela::render
