#pragma once
// The scene's lights on the GPU as structure-of-arrays: five vec4 streams of `capacity` entries
// each (see lightData in render/shaders/common/light_buffer.glsl). Only lights the frame marks
// as changed are rewritten; growing the capacity rewrites all.
#include <cstdint>
#include <span>

#include "candela/render/frame_scene.h"
#include "candela/render/gpu_buffer.h"

namespace candela::render {

class AreaLightTextures;
class GpuContext;

class GpuLightBuffer {
public:
    static constexpr uint32_t kStreams = 5;

    // Brings the buffer in line with `lights`; rewrites `changed` slots, or all of them when
    // `rewriteAll` (new or removed lights, first use). `textures`: where textured rects' images
    // sit (null: every rect untextured).
    void update(GpuContext& context, std::span<const LightInstance> lights,
                std::span<const uint32_t> changed, bool rewriteAll,
                const AreaLightTextures* textures = nullptr);

    const GpuBuffer& buffer() const { return buffer_; }
    uint32_t capacity() const { return capacity_; }
    uint32_t count() const { return count_; }
    uint32_t rewrittenLastUpdate() const { return rewritten_; }

private:
    void write(uint32_t slot, const LightInstance& light, const AreaLightTextures* textures);

    GpuBuffer buffer_;
    uint32_t capacity_ = 0;
    uint32_t count_ = 0;
    uint32_t rewritten_ = 0;
};

}  // namespace candela::render
