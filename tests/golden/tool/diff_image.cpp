#include "diff_image.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace candela::golden {

namespace {

constexpr double kLumaR = 0.2126, kLumaG = 0.7152, kLumaB = 0.0722;

std::uint8_t level(double value) {
    return std::uint8_t(std::clamp(value, 0.0, 255.0) + 0.5);
}

}  // namespace

std::vector<float> backdropFromLdr(const LdrImage& image) {
    std::vector<float> grey(image.pixelCount());
    for (std::size_t i = 0; i < grey.size(); ++i) {
        grey[i] = float(kLumaR * image.rgb[i * 3] + kLumaG * image.rgb[i * 3 + 1] +
                        kLumaB * image.rgb[i * 3 + 2]);
    }
    return grey;
}

std::vector<float> backdropFromHdr(const HdrImage& image) {
    std::vector<double> luminance(image.pixelCount());
    double sum = 0;
    for (std::size_t i = 0; i < luminance.size(); ++i) {
        double y = kLumaR * image.rgb[i * 3] + kLumaG * image.rgb[i * 3 + 1] +
                   kLumaB * image.rgb[i * 3 + 2];
        luminance[i] = std::isfinite(y) ? std::max(y, 0.0) : 0.0;
        sum += luminance[i];
    }
    // Scaling by the mean puts the average pixel at mid grey whatever the exposure.
    const double scale = sum > 0 ? double(luminance.size()) / sum : 1.0;
    std::vector<float> grey(luminance.size());
    for (std::size_t i = 0; i < grey.size(); ++i) {
        double x = luminance[i] * scale;
        grey[i] = float(255.0 * x / (1.0 + x));
    }
    return grey;
}

LdrImage falseColourDiff(const std::vector<float>& errorInTolerances,
                         const std::vector<float>& backdrop, std::uint32_t width,
                         std::uint32_t height, double hardLimitInTolerances) {
    LdrImage diff;
    diff.width = width;
    diff.height = height;
    diff.rgb.resize(diff.pixelCount() * 3);
    const double logLimit = std::log(std::max(hardLimitInTolerances, 1.0 + 1e-6));
    for (std::size_t i = 0; i < diff.pixelCount(); ++i) {
        const double e = errorInTolerances[i];
        std::uint8_t* out = &diff.rgb[i * 3];
        if (e == 0) {
            const std::uint8_t grey = level(0.35 * backdrop[i]);
            out[0] = out[1] = out[2] = grey;
        } else if (e <= 1) {
            out[0] = 0;
            out[1] = level(40 * e);
            out[2] = level(110 + 145 * e);
        } else if (e <= hardLimitInTolerances) {
            const double t = std::log(e) / logLimit;  // 0 at the tolerance, 1 at the limit
            out[0] = 255;
            out[1] = level(255 - 135 * t);
            out[2] = 0;
        } else {
            out[0] = 255;
            out[1] = 0;
            out[2] = 0;
        }
    }
    return diff;
}

}  // namespace candela::golden
