#pragma once
// False-colour difference images: where, and by how much, actual and expected differ.
//
//   dim grey   identical (the expected image's luma, darkened, for orientation)
//   blue       differs, within tolerance (brighter blue: closer to the tolerance)
//   yellow     over tolerance; shades to orange as the error nears the hard limit
//   red        over the hard limit
#include <vector>

#include "golden_image.h"

namespace candela::golden {

// Backdrops: the expected image as 0..255 grey, so the colours can be placed in the scene.
std::vector<float> backdropFromLdr(const LdrImage& image);
std::vector<float> backdropFromHdr(const HdrImage& image);  // luminance over its mean, x/(1+x)

// `errorInTolerances` is DifferenceStats::errorInTolerances; `hardLimitInTolerances` where
// yellow/orange turns red.
LdrImage falseColourDiff(const std::vector<float>& errorInTolerances,
                         const std::vector<float>& backdrop, std::uint32_t width,
                         std::uint32_t height, double hardLimitInTolerances);

}  // namespace candela::golden
