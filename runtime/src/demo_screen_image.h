#pragma once
// The demo hall's screen (issue 15's textured rect light): a test card made in code, so the demo
// needs no image file.
#include <memory>

#include "candela/content/image.h"

namespace candela::runtime {

// 128 x 72 sRGB: seven colour bars over a grey ramp, a white frame.
std::shared_ptr<const content::Rgba8Image> demoScreenImage();

}  // namespace candela::runtime
