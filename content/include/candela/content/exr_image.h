#pragma once
// OpenEXR reading into linear float RGBA, and writing float RGB (frame captures).
//
// Reading never throws and never trusts the file: the header's data window is checked against
// ExrLimits before any pixel memory is allocated, OpenEXR exceptions become Diagnostics, and
// NaN/Inf channels are made finite (NaN, -Inf -> 0; +Inf -> 65504, the largest half) and
// reported as a warning.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

#include "candela/content/diagnostics.h"
#include "candela/content/float_image.h"

namespace candela::content {

struct ExrLimits {
    std::uint32_t maxDimension = 16384;            // per axis, texels
    std::uint64_t maxTexels = 16384ull * 8192ull;  // 2 GiB of float RGBA at most
    std::uint64_t maxFileBytes = 1024ull * 1024 * 1024;
};

// What OpenEXR's standard "envmap" header attribute says the image is.
enum class ExrEnvmapAttribute { Absent, LatLong, Cube };

struct ExrImage {
    FloatImage image;  // R, G, B from the file; A from the file or 1
    ExrEnvmapAttribute envmap = ExrEnvmapAttribute::Absent;
    std::uint64_t replacedNonFiniteTexels = 0;  // texels that had a NaN/Inf channel
};

std::optional<ExrImage> readExrImage(const std::filesystem::path& path, Diagnostics& diagnostics,
                                     const ExrLimits& limits = {});
// `name` only labels diagnostics.
std::optional<ExrImage> readExrImageFromMemory(std::span<const std::byte> bytes,
                                               const std::string& name, Diagnostics& diagnostics,
                                               const ExrLimits& limits = {});

// Writes `rgb` (width * height * 3 floats, row-major, top row first) as a 32-bit float RGB
// EXR with ZIP compression. Returns an empty string on success, else what went wrong.
std::string writeExrRgbFloat(const std::filesystem::path& path, std::uint32_t width,
                             std::uint32_t height, const float* rgb);

}  // namespace candela::content
