#pragma once
// PNG/JPEG decoding to RGBA8 with the dimensions checked before any texel memory is allocated.
#include <cstdint>
#include <span>
#include <string>

#include "candela/content/image.h"

namespace candela::content {

struct ImageDecodeLimits {
    std::uint32_t maxDimension = 16384;
    std::uint64_t maxTexels = 8192ull * 8192ull;
};

// Returns an empty string and fills `image` on success, else the problem.
std::string decodeImageRgba8(std::span<const std::uint8_t> bytes, Rgba8Image& image,
                             const ImageDecodeLimits& limits = {});

}  // namespace candela::content
