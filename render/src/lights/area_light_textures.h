#pragma once
// The emissive images of textured rect lights (issue 15, content::Light::texture) in one
// atlas for the lighting shaders (common/area_light_texture.glsl): each image resampled to a
// kTileSize square tile, the tiles side by side in one row, with a box-filtered mip chain down
// to one texel per tile. The chain is the pre-filtered texture of Heitz et al. 2016 (LTC area
// lights, section 5.3): the shaders read the mip whose texels match the lobe's footprint on the
// light. Tiles are powers of two, so every level stays aligned to them and no level mixes two
// images. Texels are linear RGB divided by the image's average luminance (Rec. 709 Y): the
// light's luminance lumens / (pi area) is then the average over the rect, as for an untextured
// rect, and the image only redistributes it.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "candela/content/image.h"
#include "candela/render/frame_scene.h"
#include "candela/render/gpu_image.h"
#include "vk/sampler.h"

namespace candela::render {

class GpuContext;

class AreaLightTextures {
public:
    static constexpr uint32_t kTileSize = 256;  // AREA_LIGHT_TEXTURE_TILE in the GLSL
    static constexpr uint32_t kMipLevels = 9;   // 256 .. 1 texel per tile

    explicit AreaLightTextures(GpuContext& context);

    // Brings the atlas in line with the images of `lights`' rects, in order of first use.
    // Returns true when the tiles changed (every light must then be packed again for its
    // slot). Rebuilding waits for the device to go idle: images change on load and in the
    // editor, not per frame.
    bool update(GpuContext& context, std::span<const LightInstance> lights);

    // 1 + the tile holding the image of content::Light::texture `textureId`; 0 (untextured)
    // for none or an image not in the atlas.
    uint32_t slotOf(uint32_t textureId) const;
    uint32_t tileCount() const { return uint32_t(images_.size()); }

    VkDescriptorImageInfo descriptor() const;

private:
    std::vector<std::shared_ptr<const content::Rgba8Image>> images_;
    GpuImage atlas_;
    Sampler sampler_;
};

// The atlas's texels (linear RGBA float, every mip level in order, rows top first) for
// `images`, each normalised to an average luminance of 1 (an all-black image stays black).
std::vector<float> areaLightAtlasTexels(std::span<const content::Rgba8Image* const> images);

}  // namespace candela::render
