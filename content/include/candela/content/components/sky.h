#pragma once
// Sky component: an HDR environment from an OpenEXR file (lat-long or cube, see exr_image.h).
#include <string>

namespace candela::content {

struct Sky {
    std::string exrPath;     // relative to the scene file
    float intensity = 1.0f;  // multiplies the environment's linear radiance
};

}  // namespace candela::content
