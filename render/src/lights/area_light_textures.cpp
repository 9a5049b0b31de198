#include "lights/area_light_textures.h"

#include <algorithm>
#include <glm/gtc/packing.hpp>

#include "candela/content/light_texture.h"
#include "candela/content/mip_generation.h"
#include "candela/render/gpu_context.h"
#include "vk/image_transfer.h"

namespace candela::render {

namespace {

constexpr uint32_t kTile = AreaLightTextures::kTileSize;

// A kTile square of linear RGB from `image`: each texel the mean of the source texels whose
// centres fall in it (the nearest one when the source is smaller), scaled to average luminance
// 1.
std::vector<float> resampledTile(const content::Rgba8Image& image) {
    std::vector<float> tile(size_t(kTile) * kTile * 4, 0.0f);
    double luminanceSum = 0.0;
    for (uint32_t y = 0; y < kTile; ++y) {
        const uint32_t y0 = y * image.height / kTile;
        const uint32_t y1 = std::max(y0 + 1, (y + 1) * image.height / kTile);
        for (uint32_t x = 0; x < kTile; ++x) {
            const uint32_t x0 = x * image.width / kTile;
            const uint32_t x1 = std::max(x0 + 1, (x + 1) * image.width / kTile);
            float rgb[3] = {0.0f, 0.0f, 0.0f};
            for (uint32_t sy = y0; sy < y1; ++sy) {
                for (uint32_t sx = x0; sx < x1; ++sx) {
                    const uint8_t* texel = &image.rgba[(size_t(sy) * image.width + sx) * 4];
                    for (int c = 0; c < 3; ++c)
                        rgb[c] += content::srgbToLinear(texel[c]);
                }
            }
            const float count = float((y1 - y0) * (x1 - x0));
            float* out = &tile[(size_t(y) * kTile + x) * 4];
            for (int c = 0; c < 3; ++c)
                out[c] = rgb[c] / count;
            out[3] = 1.0f;
            luminanceSum += 0.2126 * out[0] + 0.7152 * out[1] + 0.0722 * out[2];
        }
    }
    const double average = luminanceSum / (double(kTile) * kTile);
    const float scale = average > 0.0 ? float(1.0 / average) : 0.0f;
    for (size_t i = 0; i < tile.size(); i += 4) {
        for (int c = 0; c < 3; ++c)
            tile[i + c] *= scale;
    }
    return tile;
}

ImageDesc atlasDesc(uint32_t tiles) {
    return {VK_FORMAT_R16G16B16A16_SFLOAT,
            tiles * kTile,
            kTile,
            AreaLightTextures::kMipLevels,
            false,
            VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT};
}

// A 1x1 stand-in while no rect is textured: the shaders never read it (slot 0).
ImageDesc placeholderDesc() {
    return {VK_FORMAT_R16G16B16A16_SFLOAT,
            1,
            1,
            1,
            false,
            VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT};
}

std::vector<uint16_t> toHalf(const std::vector<float>& texels) {
    std::vector<uint16_t> half(texels.size());
    for (size_t i = 0; i < texels.size(); ++i)
        half[i] = uint16_t(glm::packHalf1x16(texels[i]));
    return half;
}

}  // namespace

std::vector<float> areaLightAtlasTexels(std::span<const content::Rgba8Image* const> images) {
    const uint32_t tiles = uint32_t(images.size());
    uint32_t width = tiles * kTile;
    std::vector<float> level(size_t(width) * kTile * 4);
    for (uint32_t t = 0; t < tiles; ++t) {
        const std::vector<float> tile = resampledTile(*images[t]);
        for (uint32_t y = 0; y < kTile; ++y) {
            std::copy_n(&tile[size_t(y) * kTile * 4], kTile * 4,
                        &level[(size_t(y) * width + size_t(t) * kTile) * 4]);
        }
    }
    std::vector<float> all = level;
    // Each level the 2 x 2 mean of the one above: tiles are 2^n wide, so no texel straddles two.
    for (uint32_t m = 1, height = kTile; m < AreaLightTextures::kMipLevels; ++m) {
        const uint32_t w = width / 2, h = height / 2;
        std::vector<float> next(size_t(w) * h * 4);
        for (uint32_t y = 0; y < h; ++y) {
            for (uint32_t x = 0; x < w; ++x) {
                for (int c = 0; c < 4; ++c) {
                    auto at = [&](uint32_t sx, uint32_t sy) {
                        return level[(size_t(sy) * width + sx) * 4 + c];
                    };
                    next[(size_t(y) * w + x) * 4 + c] =
                        0.25f * (at(2 * x, 2 * y) + at(2 * x + 1, 2 * y) + at(2 * x, 2 * y + 1) +
                                 at(2 * x + 1, 2 * y + 1));
                }
            }
        }
        all.insert(all.end(), next.begin(), next.end());
        level = std::move(next);
        width = w;
        height = h;
    }
    return all;
}

AreaLightTextures::AreaLightTextures(GpuContext& context)
    : atlas_(context, placeholderDesc()), sampler_(context, SamplerDesc{VK_FILTER_LINEAR, true}) {
    const std::vector<uint16_t> one = toHalf({1.0f, 1.0f, 1.0f, 1.0f});
    writeImage(context, atlas_, 8, reinterpret_cast<const uint8_t*>(one.data()));
}

bool AreaLightTextures::update(GpuContext& context, std::span<const LightInstance> lights) {
    std::vector<std::shared_ptr<const content::Rgba8Image>> images;
    for (const LightInstance& l : lights) {
        if (l.light.type != content::LightType::Rect || l.light.texture == 0) continue;
        const auto texture = content::findLightTexture(l.light.texture);
        const auto image = texture ? texture->image : nullptr;
        if (!image || image->width == 0 || image->height == 0 ||
            image->rgba.size() < size_t(image->width) * image->height * 4) {
            continue;
        }
        if (std::find(images.begin(), images.end(), image) == images.end()) images.push_back(image);
    }
    if (images == images_) return false;
    vkDeviceWaitIdle(context.device());  // frames in flight may still read the old atlas
    images_ = std::move(images);
    if (images_.empty()) {
        atlas_ = GpuImage(context, placeholderDesc());
        const std::vector<uint16_t> one = toHalf({1.0f, 1.0f, 1.0f, 1.0f});
        writeImage(context, atlas_, 8, reinterpret_cast<const uint8_t*>(one.data()));
        return true;
    }
    std::vector<const content::Rgba8Image*> raw;
    for (const auto& image : images_)
        raw.push_back(image.get());
    const std::vector<uint16_t> texels = toHalf(areaLightAtlasTexels(raw));
    atlas_ = GpuImage(context, atlasDesc(uint32_t(raw.size())));
    writeImage(context, atlas_, 8, reinterpret_cast<const uint8_t*>(texels.data()));
    return true;
}

uint32_t AreaLightTextures::slotOf(uint32_t textureId) const {
    if (textureId == 0 || images_.empty()) return 0;
    const auto texture = content::findLightTexture(textureId);
    const content::Rgba8Image* image = texture ? texture->image.get() : nullptr;
    if (!image) return 0;
    for (size_t i = 0; i < images_.size(); ++i) {
        if (images_[i].get() == image) return uint32_t(i + 1);
    }
    return 0;
}

VkDescriptorImageInfo AreaLightTextures::descriptor() const {
    return {sampler_.handle(), atlas_.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
}

}  // namespace candela::render
