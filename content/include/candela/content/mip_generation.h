#pragma once
// CPU mip chains for RGBA8 textures. sRGB textures are averaged in linear light (decode,
// average, re-encode), so dark/bright detail does not shift brightness as it minifies; linear
// data (normals, roughness) is averaged as stored. Alpha is always linear.
#include <vector>

#include "candela/content/image.h"

namespace candela::content {

// Level 0 is the image itself; each next level halves width and height (rounding down, at
// least 1) with a box filter over the 2x2 (or 2x1, 1x2) parent texels, down to 1x1.
std::vector<Rgba8Image> generateMipChain(const Rgba8Image& image, ColorSpace colorSpace);

float srgbToLinear(std::uint8_t value);
std::uint8_t linearToSrgb(float linear);

}  // namespace candela::content
