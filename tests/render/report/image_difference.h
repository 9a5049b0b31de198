#pragma once
// Differences between two HDR captures over a set of pixels, relative to the reference's mean
// radiance there (so scenes of any brightness compare).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "candela/render/frame_capture.h"

namespace candela::report {

struct ImageDifference {
    double relativeRmse = 0.0;  // RMSE over pixels and channels / mean reference
    double relativeMax = 0.0;   // largest absolute difference / mean reference
    double relativeBias = 0.0;  // (mean - mean reference) / mean reference
    uint32_t worstX = 0, worstY = 0;
    size_t pixels = 0;
};

// include(x, y): whether the pixel counts.
template <class Include>
ImageDifference imageDifference(const render::CapturedFrame& image,
                                const render::CapturedFrame& reference, Include include) {
    double sumSquared = 0.0, sumReference = 0.0, sumImage = 0.0, maxAbs = 0.0;
    ImageDifference out;
    size_t values = 0;
    for (uint32_t y = 0; y < image.height; ++y) {
        for (uint32_t x = 0; x < image.width; ++x) {
            if (!include(x, y)) continue;
            ++out.pixels;
            for (int c = 0; c < 3; ++c) {
                const size_t i = (size_t(y) * image.width + x) * 3 + c;
                const double a = image.hdrRgb[i], r = reference.hdrRgb[i];
                sumSquared += (a - r) * (a - r);
                sumReference += r;
                sumImage += a;
                if (!(std::fabs(a - r) <= maxAbs)) {
                    maxAbs = std::fabs(a - r);
                    out.worstX = x;
                    out.worstY = y;
                }
                ++values;
            }
        }
    }
    const double mean = sumReference / double(std::max<size_t>(values, 1));
    out.relativeRmse = std::sqrt(sumSquared / double(std::max<size_t>(values, 1))) / mean;
    out.relativeMax = maxAbs / mean;
    out.relativeBias = (sumImage - sumReference) / sumReference;
    return out;
}

}  // namespace candela::report
