#pragma once
// Decoded 8-bit RGBA images and how they are sampled.
#include <cstdint>
#include <vector>

namespace candela::content {

// How texel values are encoded: sRGB for colours people look at (base colour, emissive),
// linear for data (normals, metallic/roughness, occlusion).
enum class ColorSpace : std::uint8_t { Srgb, Linear };

struct Rgba8Image {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<std::uint8_t> rgba;  // width * height * 4 bytes, row-major, top row first
    bool isFallback = false;         // the magenta checker that stands in for a missing image
};

enum class Filter : std::uint8_t { Nearest, Linear };
enum class Wrap : std::uint8_t { Repeat, ClampToEdge, MirroredRepeat };

struct Sampler {
    Filter magFilter = Filter::Linear;
    Filter minFilter = Filter::Linear;
    Filter mipFilter = Filter::Linear;
    bool useMipmaps = true;  // false for glTF's NEAREST/LINEAR minFilter (no mip level named)
    Wrap wrapS = Wrap::Repeat;
    Wrap wrapT = Wrap::Repeat;
};

// An 8x8 magenta/black checker: unmistakable on screen, so a missing texture is noticed.
Rgba8Image makeFallbackCheckerImage();

}  // namespace candela::content
