#pragma once
// Changes the self tests make to captures, each standing for something a golden must catch
// (a local change, a shifted image) or must let through (rounding noise).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <type_traits>

#include "golden_image.h"

namespace candela::golden::test {

// Multiplies a size x size block with its top-left corner at x0, y0 by `factor`.
template <typename Image>
Image scaleBlock(Image image, std::uint32_t x0, std::uint32_t y0, std::uint32_t size,
                 double factor) {
    using Channel = typename decltype(image.rgb)::value_type;
    for (std::uint32_t y = y0; y < y0 + size; ++y) {
        for (std::uint32_t x = x0; x < x0 + size; ++x) {
            for (std::size_t c = 0; c < 3; ++c) {
                Channel& value = image.rgb[(std::size_t(y) * image.width + x) * 3 + c];
                double scaled = double(value) * factor;
                if constexpr (std::is_integral_v<Channel>) scaled = std::min(255.0, scaled + 0.5);
                value = Channel(scaled);
            }
        }
    }
    return image;
}

// Moves the content `pixels` to the right; the first column repeats into the gap.
template <typename Image>
Image shiftedRight(const Image& image, std::uint32_t pixels) {
    Image shifted = image;
    for (std::uint32_t y = 0; y < image.height; ++y) {
        for (std::uint32_t x = 0; x < image.width; ++x) {
            std::uint32_t from = x >= pixels ? x - pixels : 0;
            for (std::size_t c = 0; c < 3; ++c) {
                shifted.rgb[(std::size_t(y) * image.width + x) * 3 + c] =
                    image.rgb[(std::size_t(y) * image.width + from) * 3 + c];
            }
        }
    }
    return shifted;
}

// Every channel of every pixel one float ulp up or down at random: what a changed rounding
// mode, FMA contraction or driver math library does at most to well-conditioned shading.
inline HdrImage withUlpNoise(HdrImage image, unsigned seed) {
    std::mt19937 random(seed);
    for (float& value : image.rgb) {
        const float toward =
            (random() & 1) ? std::numeric_limits<float>::max() : -std::numeric_limits<float>::max();
        value = std::nextafter(value, toward);
    }
    return image;
}

// `levels` added to or taken from every channel of a random `fraction` of the pixels.
inline LdrImage withLevelNoise(LdrImage image, double fraction, int levels, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> chance(0.0, 1.0);
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        if (chance(random) >= fraction) continue;
        const int sign = (random() & 1) ? 1 : -1;
        for (std::size_t c = 0; c < 3; ++c) {
            std::uint8_t& value = image.rgb[i * 3 + c];
            int moved = int(value) + sign * levels;
            if (moved < 0 || moved > 255) moved = int(value) - sign * levels;
            value = std::uint8_t(moved);
        }
    }
    return image;
}

}  // namespace candela::golden::test
