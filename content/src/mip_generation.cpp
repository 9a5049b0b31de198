#include "candela/content/mip_generation.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace candela::content {
namespace {

const std::array<float, 256>& srgbTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) {
            const float c = static_cast<float>(i) / 255.0f;
            t[static_cast<std::size_t>(i)] =
                c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
        }
        return t;
    }();
    return table;
}

std::uint8_t toByte(float unit) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(unit, 0.0f, 1.0f) * 255.0f));
}

Rgba8Image halve(const Rgba8Image& src, ColorSpace colorSpace) {
    Rgba8Image dst;
    dst.width = std::max(1u, src.width / 2);
    dst.height = std::max(1u, src.height / 2);
    dst.isFallback = src.isFallback;
    dst.rgba.resize(std::size_t{dst.width} * dst.height * 4);
    const bool srgb = colorSpace == ColorSpace::Srgb;
    for (std::uint32_t y = 0; y < dst.height; ++y) {
        for (std::uint32_t x = 0; x < dst.width; ++x) {
            // Parent texels covered (clamped for odd or 1-texel dimensions).
            const std::uint32_t x0 = std::min(2 * x, src.width - 1);
            const std::uint32_t x1 = std::min(2 * x + 1, src.width - 1);
            const std::uint32_t y0 = std::min(2 * y, src.height - 1);
            const std::uint32_t y1 = std::min(2 * y + 1, src.height - 1);
            const std::uint32_t xs[2] = {x0, x1};
            const std::uint32_t ys[2] = {y0, y1};
            std::array<float, 4> sum{};
            for (std::uint32_t sy : ys) {
                for (std::uint32_t sx : xs) {
                    const std::uint8_t* t = &src.rgba[(std::size_t{sy} * src.width + sx) * 4];
                    for (int c = 0; c < 3; ++c) {
                        sum[c] += srgb ? srgbTable()[t[c]] : static_cast<float>(t[c]) / 255.0f;
                    }
                    sum[3] += static_cast<float>(t[3]) / 255.0f;
                }
            }
            std::uint8_t* out = &dst.rgba[(std::size_t{y} * dst.width + x) * 4];
            for (int c = 0; c < 3; ++c) {
                const float average = sum[c] / 4.0f;
                out[c] = srgb ? linearToSrgb(average) : toByte(average);
            }
            out[3] = toByte(sum[3] / 4.0f);
        }
    }
    return dst;
}

}  // namespace

float srgbToLinear(std::uint8_t value) {
    return srgbTable()[value];
}

std::uint8_t linearToSrgb(float linear) {
    const float l = std::clamp(linear, 0.0f, 1.0f);
    const float encoded = l <= 0.0031308f ? l * 12.92f : 1.055f * std::pow(l, 1.0f / 2.4f) - 0.055f;
    return toByte(encoded);
}

std::vector<Rgba8Image> generateMipChain(const Rgba8Image& image, ColorSpace colorSpace) {
    std::vector<Rgba8Image> chain;
    if (image.width == 0 || image.height == 0 ||
        image.rgba.size() != std::size_t{image.width} * image.height * 4) {
        return chain;
    }
    chain.push_back(image);
    while (chain.back().width > 1 || chain.back().height > 1) {
        chain.push_back(halve(chain.back(), colorSpace));
    }
    return chain;
}

}  // namespace candela::content
