#pragma once
// The two images a golden test compares: the HDR capture (linear scene radiance in cd/m^2)
// and the tonemapped sRGB PNG. Both are RGB, row-major, top row first.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace candela::golden {

struct HdrImage {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<float> rgb;  // width * height * 3, cd/m^2

    std::size_t pixelCount() const { return std::size_t(width) * height; }
};

struct LdrImage {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<std::uint8_t> rgb;  // width * height * 3, sRGB-encoded levels 0..255

    std::size_t pixelCount() const { return std::size_t(width) * height; }
};

}  // namespace candela::golden
