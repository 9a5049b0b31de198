#include "lights/gpu_light_buffer.h"

#include <algorithm>
#include <glm/glm.hpp>

#include "gpu_light.h"
#include "lights/area_light_textures.h"

namespace candela::render {

void GpuLightBuffer::update(GpuContext& context, std::span<const LightInstance> lights,
                            std::span<const uint32_t> changed, bool rewriteAll,
                            const AreaLightTextures* textures) {
    count_ = uint32_t(lights.size());
    if (count_ > capacity_ || !buffer_.handle()) {
        capacity_ = std::max<uint32_t>(64, std::max(count_, capacity_ * 2));
        buffer_ = GpuBuffer(context, VkDeviceSize(capacity_) * kStreams * sizeof(glm::vec4),
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryLocation::HostVisible);
        rewriteAll = true;
    }
    rewritten_ = 0;
    if (rewriteAll) {
        for (uint32_t i = 0; i < count_; ++i)
            write(i, lights[i], textures);
        rewritten_ = count_;
        return;
    }
    for (uint32_t slot : changed) {
        if (slot < count_) {
            write(slot, lights[slot], textures);
            ++rewritten_;
        }
    }
}

void GpuLightBuffer::write(uint32_t slot, const LightInstance& light,
                           const AreaLightTextures* textures) {
    const GpuLight g = packLight(light, textures ? textures->slotOf(light.light.texture) : 0u);
    auto* streams = static_cast<glm::vec4*>(buffer_.mapped());
    glm::vec4* stream[kStreams];
    for (uint32_t s = 0; s < kStreams; ++s)
        stream[s] = streams + size_t(s) * capacity_;
    stream[0][slot] = {g.position[0], g.position[1], g.position[2], g.invAttenuationRadius};
    stream[1][slot] = {g.intensity[0], g.intensity[1], g.intensity[2], g.sourceRadius};
    stream[2][slot] = {g.direction[0], g.direction[1], g.direction[2], g.sourceLength};
    stream[3][slot] = {g.tubeAxis[0], g.tubeAxis[1], g.tubeAxis[2], float(g.type)};
    stream[4][slot] = {g.spotScale, g.spotOffset, g.shape[0], g.shape[1]};
}

}  // namespace candela::render
