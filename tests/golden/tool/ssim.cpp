#include "ssim.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace candela::golden {

namespace {

constexpr int kRadius = 5;
constexpr double kSigma = 1.5;
constexpr double kC1 = (0.01 * 255) * (0.01 * 255);
constexpr double kC2 = (0.03 * 255) * (0.03 * 255);

std::array<double, 2 * kRadius + 1> gaussianWeights() {
    std::array<double, 2 * kRadius + 1> weights{};
    for (int i = -kRadius; i <= kRadius; ++i) {
        weights[i + kRadius] = std::exp(-double(i * i) / (2 * kSigma * kSigma));
    }
    return weights;
}

std::vector<double> luma(const LdrImage& image) {
    std::vector<double> y(image.pixelCount());
    for (std::size_t i = 0; i < y.size(); ++i) {
        y[i] = 0.2126 * image.rgb[i * 3] + 0.7152 * image.rgb[i * 3 + 1] +
               0.0722 * image.rgb[i * 3 + 2];
    }
    return y;
}

// One axis of the Gaussian blur, the window clipped to the image and renormalised. Doing
// both axes this way renormalises the clipped 2D window exactly (its weight is a product).
std::vector<double> blurAxis(const std::vector<double>& source, int width, int height,
                             bool horizontal) {
    static const auto weights = gaussianWeights();
    std::vector<double> result(source.size());
    const int length = horizontal ? width : height;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const int at = horizontal ? x : y;
            double sum = 0, weightSum = 0;
            for (int k = std::max(-kRadius, -at); k <= std::min(kRadius, length - 1 - at); ++k) {
                const int sx = horizontal ? x + k : x;
                const int sy = horizontal ? y : y + k;
                sum += weights[k + kRadius] * source[std::size_t(sy) * width + sx];
                weightSum += weights[k + kRadius];
            }
            result[std::size_t(y) * width + x] = sum / weightSum;
        }
    }
    return result;
}

std::vector<double> blur(const std::vector<double>& source, int width, int height) {
    return blurAxis(blurAxis(source, width, height, true), width, height, false);
}

}  // namespace

SsimResult ssimOfLuma(const LdrImage& actual, const LdrImage& expected) {
    const int width = int(actual.width), height = int(actual.height);
    const std::vector<double> a = luma(actual), b = luma(expected);
    std::vector<double> aa(a.size()), bb(a.size()), ab(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        aa[i] = a[i] * a[i];
        bb[i] = b[i] * b[i];
        ab[i] = a[i] * b[i];
    }
    const std::vector<double> meanA = blur(a, width, height), meanB = blur(b, width, height);
    const std::vector<double> meanAA = blur(aa, width, height), meanBB = blur(bb, width, height);
    const std::vector<double> meanAB = blur(ab, width, height);

    SsimResult result;
    result.map.resize(a.size());
    double sum = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const double varianceA = meanAA[i] - meanA[i] * meanA[i];
        const double varianceB = meanBB[i] - meanB[i] * meanB[i];
        const double covariance = meanAB[i] - meanA[i] * meanB[i];
        const double score =
            (2 * meanA[i] * meanB[i] + kC1) * (2 * covariance + kC2) /
            ((meanA[i] * meanA[i] + meanB[i] * meanB[i] + kC1) * (varianceA + varianceB + kC2));
        result.map[i] = float(score);
        result.min = std::min(result.min, score);
        sum += score;
    }
    result.mean = a.empty() ? 1.0 : sum / double(a.size());
    return result;
}

}  // namespace candela::golden
