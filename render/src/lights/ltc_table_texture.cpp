#include "lights/ltc_table_texture.h"

#include <array>
#include <cstdint>
#include <glm/gtc/packing.hpp>
#include <vector>

#include "../../ltc/ltc_ggx_table.inc"
#include "vk/image_transfer.h"

namespace candela::render {

namespace {

ImageDesc tableDesc() {
    return {VK_FORMAT_R16G16B16A16_SFLOAT,
            uint32_t(kLtcTableSize),
            uint32_t(kLtcTableSize),
            1,
            false,
            VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT};
}

// Four entries of every cell from `first`, as half floats (zeros past the sixth).
std::vector<uint8_t> halfTexels(int first) {
    std::vector<uint16_t> texels;
    texels.reserve(size_t(kLtcTableSize) * kLtcTableSize * 4);
    for (const auto& cell : kLtcTable) {
        for (int k = first; k < first + 4; ++k)
            texels.push_back(uint16_t(glm::packHalf1x16(k < 6 ? cell[k] : 0.0f)));
    }
    const auto* bytes = reinterpret_cast<const uint8_t*>(texels.data());
    return std::vector<uint8_t>(bytes, bytes + texels.size() * sizeof(uint16_t));
}

}  // namespace

LtcTableTexture::LtcTableTexture(GpuContext& context)
    : matrix_(context, tableDesc()),
      magnitude_(context, tableDesc()),
      sampler_(context, SamplerDesc{}) {
    writeImage(context, matrix_, 8, halfTexels(0).data());
    writeImage(context, magnitude_, 8, halfTexels(4).data());
}

VkDescriptorImageInfo LtcTableTexture::matrix() const {
    return {sampler_.handle(), matrix_.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
}

VkDescriptorImageInfo LtcTableTexture::magnitude() const {
    return {sampler_.handle(), magnitude_.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
}

}  // namespace candela::render
