#pragma once
// A linear-light float RGBA image on the CPU: what HDR loaders produce and IBL code consumes.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace candela::content {

struct FloatImage {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<float> rgba;  // width * height * 4 floats, row-major, top row first

    const float* texel(std::uint32_t x, std::uint32_t y) const {
        return rgba.data() + (static_cast<std::size_t>(y) * width + x) * 4;
    }
    float* texel(std::uint32_t x, std::uint32_t y) {
        return rgba.data() + (static_cast<std::size_t>(y) * width + x) * 4;
    }
};

}  // namespace candela::content
