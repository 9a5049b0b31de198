#pragma once
// Structural similarity (Wang, Bovik, Sheikh, Simoncelli 2004) of two tonemapped images,
// on their sRGB luma: the score that drops for shifted edges, blur and lost detail even when
// few pixels change much.
#include <vector>

#include "golden_image.h"

namespace candela::golden {

struct SsimResult {
    double mean = 1.0;
    double min = 1.0;
    std::vector<float> map;  // per pixel, 1 where the neighbourhoods match
};

// Luma Y = 0.2126 R + 0.7152 G + 0.0722 B of the encoded levels; 11x11 Gaussian window with
// sigma 1.5; C1 = (0.01 * 255)^2, C2 = (0.03 * 255)^2, as in the paper. At the borders the
// window is clipped to the image and renormalised, so every pixel has a score. Both images
// must have the same size.
SsimResult ssimOfLuma(const LdrImage& actual, const LdrImage& expected);

}  // namespace candela::golden
