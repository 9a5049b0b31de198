#pragma once
// A small synthetic "render" for testing the metrics without a GPU: a radiance gradient with
// a bright disc and a dark square, and its tonemapped PNG (exposure 1, Reinhard, sRGB).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "golden_image.h"

namespace candela::golden::test {

inline HdrImage syntheticHdr(std::uint32_t width = 128, std::uint32_t height = 128) {
    HdrImage image{width, height, {}};
    image.rgb.resize(image.pixelCount() * 3);
    for (std::uint32_t y = 0; y < height; ++y) {
        for (std::uint32_t x = 0; x < width; ++x) {
            const double u = (x + 0.5) / width, v = (y + 0.5) / height;
            double r = 0.05 + 0.5 * u, g = 0.1 + 0.3 * v, b = 0.2;
            if (std::hypot(u - 0.35, v - 0.4) < 0.2) r = 20.0, g = 8.0, b = 2.0;
            if (u > 0.6 && u < 0.9 && v > 0.55 && v < 0.85) r = g = b = 0.0;
            float* texel = &image.rgb[(std::size_t(y) * width + x) * 3];
            texel[0] = float(r), texel[1] = float(g), texel[2] = float(b);
        }
    }
    return image;
}

inline LdrImage tonemapped(const HdrImage& hdr) {
    LdrImage image{hdr.width, hdr.height, {}};
    image.rgb.resize(hdr.rgb.size());
    for (std::size_t i = 0; i < hdr.rgb.size(); ++i) {
        const double x = hdr.rgb[i] / (1.0 + hdr.rgb[i]);
        const double encoded = x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1 / 2.4) - 0.055;
        image.rgb[i] = std::uint8_t(std::clamp(encoded, 0.0, 1.0) * 255.0 + 0.5);
    }
    return image;
}

}  // namespace candela::golden::test
