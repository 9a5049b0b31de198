#pragma once
// HDR environments from OpenEXR: lat-long kept as is, cube maps of any supported layout
// resampled into the six faces a Vulkan cube image expects.
//
//   Diagnostics diagnostics;
//   if (auto env = loadEnvironmentExr("sky.exr", diagnostics)) {
//       if (env->layout == EnvironmentLayout::Cube) upload(env->cubeFaces);  // +X,-X,+Y,-Y,+Z,-Z
//       else upload(env->latLong);
//   } else { useNeutralSky(); }
//
// Directions are world directions (+Y up, right-handed, as glTF and OpenEXR): sampling the
// cube with direction d, or the lat-long at latLongTexelPosition(d), gives the radiance
// arriving from d.
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "candela/content/diagnostics.h"
#include "candela/content/exr_image.h"
#include "candela/content/float_image.h"

namespace candela::content {

enum class EnvironmentLayout : std::uint8_t { LatLong, Cube };

// Vulkan's cube face order (array layers 0..5).
enum class CubeFace : std::uint8_t {
    PositiveX,
    NegativeX,
    PositiveY,
    NegativeY,
    PositiveZ,
    NegativeZ
};

// How the source file stored the environment (for messages and stats).
enum class EnvironmentSource : std::uint8_t {
    LatLongEnvmap,    // envmap attribute "latlong"
    CubeEnvmap,       // envmap attribute "cube": OpenEXR's vertical strip of 6 faces
    LatLongByAspect,  // no attribute, 2:1
    VerticalStrip,    // no attribute, 1:6, read as OpenEXR's cube layout
    HorizontalStrip,  // no attribute, 6:1, faces +X,-X,+Y,-Y,+Z,-Z in Vulkan orientation
    HorizontalCross,  // no attribute, 4:3 (see README)
    VerticalCross,    // no attribute, 3:4, -Z at the bottom rotated 180 degrees
    LatLongAssumed,   // no attribute, other aspect: treated as lat-long with a warning
};

struct EnvironmentMap {
    EnvironmentLayout layout = EnvironmentLayout::LatLong;
    EnvironmentSource source = EnvironmentSource::LatLongAssumed;
    FloatImage latLong;                   // when layout == LatLong (OpenEXR's convention)
    std::array<FloatImage, 6> cubeFaces;  // when layout == Cube: square, Vulkan orientation
    std::uint64_t replacedNonFiniteTexels = 0;
};

std::optional<EnvironmentMap> loadEnvironmentExr(const std::filesystem::path& path,
                                                 Diagnostics& diagnostics,
                                                 const ExrLimits& limits = {});
// Layout detection and cube resampling for an image already read.
std::optional<EnvironmentMap> environmentFromExr(ExrImage image, const std::string& name,
                                                 Diagnostics& diagnostics);

// Unit direction through point (s, t) in [0,1]^2 of a Vulkan cube face (t = 0 is the top row).
std::array<float, 3> cubeFaceDirection(CubeFace face, float s, float t);

// OpenEXR lat-long convention: +Y is the top row; the centre column looks along +Z and
// x grows towards -X (longitude = atan2(x, z), column = (0.5 - longitude / 2pi) * width).
// Returns continuous texel coordinates (texel centres at i + 0.5) for direction d.
std::array<float, 2> latLongTexelPosition(const std::array<float, 3>& d, std::uint32_t width,
                                          std::uint32_t height);
std::array<float, 3> latLongDirection(float column, float row, std::uint32_t width,
                                      std::uint32_t height);

}  // namespace candela::content
