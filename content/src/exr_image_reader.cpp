// OpenEXR reading into linear float RGBA with every header value checked before use.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfEnvmapAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfPartType.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfTileDescription.h>
#include <OpenEXR/ImfVersion.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>

#include "candela/content/exr_image.h"
#include "candela/content/file_bytes.h"
#include "exr_memory_stream.h"

namespace candela::content {
namespace {

// Returns an error message, or empty when the header describes an image we can read.
std::string checkHeader(const Imf::Header& header, const ExrLimits& limits) {
    if (header.hasType() && Imf::isDeepData(header.type())) {
        return "deep EXR data is not supported (need flat RGB or RGBA)";
    }
    const Imath::Box2i& window = header.dataWindow();
    // 64-bit arithmetic: min/max come straight from the file and may be extreme.
    const std::int64_t width = std::int64_t{window.max.x} - window.min.x + 1;
    const std::int64_t height = std::int64_t{window.max.y} - window.min.y + 1;
    if (width <= 0 || height <= 0) {
        return "empty data window (" + std::to_string(width) + " x " + std::to_string(height) + ")";
    }
    if (width > limits.maxDimension || height > limits.maxDimension ||
        static_cast<std::uint64_t>(width * height) > limits.maxTexels) {
        return "data window " + std::to_string(width) + " x " + std::to_string(height) +
               " exceeds the limit of " + std::to_string(limits.maxDimension) + " per axis / " +
               std::to_string(limits.maxTexels) + " texels";
    }
    if (header.hasTileDescription()) {
        const Imf::TileDescription& tiles = header.tileDescription();
        // Tiny tiles over a large image mean a huge offset table; real files use 16 or more.
        const std::uint64_t tileCount =
            ((static_cast<std::uint64_t>(width) + tiles.xSize - 1) / std::max(tiles.xSize, 1u)) *
            ((static_cast<std::uint64_t>(height) + tiles.ySize - 1) / std::max(tiles.ySize, 1u));
        if (tiles.xSize == 0 || tiles.ySize == 0 || tiles.xSize > limits.maxDimension ||
            tiles.ySize > limits.maxDimension || tileCount > (1u << 20)) {
            return "implausible tile size " + std::to_string(tiles.xSize) + " x " +
                   std::to_string(tiles.ySize);
        }
    }
    const Imf::ChannelList& channels = header.channels();
    std::string present;
    for (auto it = channels.begin(); it != channels.end(); ++it) {
        present += present.empty() ? "" : ", ";
        present += it.name();
    }
    for (const char* name : {"R", "G", "B"}) {
        if (channels.findChannel(name) == nullptr) {
            return std::string("missing channel ") + name + " (need R, G, B and optionally A; " +
                   "file has: " + (present.empty() ? "none" : present) + ")";
        }
    }
    for (const char* name : {"R", "G", "B", "A"}) {
        const Imf::Channel* channel = channels.findChannel(name);
        if (channel != nullptr && (channel->xSampling != 1 || channel->ySampling != 1)) {
            return std::string("channel ") + name + " is subsampled, which is not supported";
        }
    }
    return {};
}

// OpenEXR's InputFile sizes its line and tile offset tables from the header before reading a
// pixel, so a forged data window makes it allocate gigabytes in its constructor. We therefore
// parse every part's header on our own first and only then hand the bytes to InputFile.
std::string checkAllHeaders(std::span<const std::byte> bytes, const char* name,
                            const ExrLimits& limits) {
    ExrMemoryStream stream(bytes, name);
    char magicAndVersion[8];
    stream.read(magicAndVersion, 8);
    int magic = 0;
    int version = 0;
    std::memcpy(&magic, magicAndVersion, 4);  // little-endian on every platform we build for
    std::memcpy(&version, magicAndVersion + 4, 4);
    if (magic != Imf::MAGIC) return "not an OpenEXR file (bad magic number)";
    if (Imf::getVersion(version) != Imf::EXR_VERSION) {
        return "unsupported OpenEXR version " + std::to_string(Imf::getVersion(version));
    }
    if (Imf::isNonImage(version)) return "deep EXR data is not supported";
    constexpr int maxParts = 16;
    for (int part = 0; part < maxParts; ++part) {
        Imf::Header header;
        header.readFrom(stream, version);
        if (std::string problem = checkHeader(header, limits); !problem.empty()) {
            return part == 0 ? problem : "part " + std::to_string(part) + ": " + problem;
        }
        if (!Imf::isMultiPart(version)) return {};
        char next = 0;  // a multi-part header list ends with an empty header (one null byte)
        const std::uint64_t position = stream.tellg();
        stream.read(&next, 1);
        if (next == 0) return {};
        stream.seekg(position);
    }
    return "more than " + std::to_string(maxParts) + " parts";
}

ExrEnvmapAttribute envmapOf(const Imf::Header& header) {
    if (!Imf::hasEnvmap(header)) return ExrEnvmapAttribute::Absent;
    switch (Imf::envmap(header)) {
        case Imf::ENVMAP_LATLONG:
            return ExrEnvmapAttribute::LatLong;
        case Imf::ENVMAP_CUBE:
            return ExrEnvmapAttribute::Cube;
        default:
            return ExrEnvmapAttribute::Absent;
    }
}

// One NaN texel would poison every mip and prefiltered IBL sample it touches, so non-finite
// channels are made finite: NaN and -Inf become 0, +Inf becomes the largest half value (a sun
// converted to half often overflows to +Inf; black there would remove the sun).
constexpr float kLargestHalf = 65504.0f;

std::uint64_t replaceNonFinite(FloatImage& image) {
    std::uint64_t replacedTexels = 0;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        bool replaced = false;
        for (std::size_t c = 0; c < 4; ++c) {
            float& v = image.rgba[i + c];
            if (std::isfinite(v)) continue;
            v = (std::isinf(v) && v > 0) ? kLargestHalf : 0.0f;
            replaced = true;
        }
        replacedTexels += replaced ? 1 : 0;
    }
    return replacedTexels;
}

}  // namespace

std::optional<ExrImage> readExrImageFromMemory(std::span<const std::byte> bytes,
                                               const std::string& name, Diagnostics& diagnostics,
                                               const ExrLimits& limits) {
    if (bytes.size() < 8) {
        diagnostics.error(name, "",
                          "not an OpenEXR file (only " + std::to_string(bytes.size()) + " bytes)");
        return std::nullopt;
    }
    ExrImage result;
    try {
        if (std::string problem = checkAllHeaders(bytes, name.c_str(), limits); !problem.empty()) {
            diagnostics.error(name, "", problem);
            return std::nullopt;
        }
        ExrMemoryStream stream(bytes, name.c_str());
        Imf::InputFile file(stream);
        const Imf::Header& header = file.header();
        const Imath::Box2i& window = header.dataWindow();
        result.image.width = static_cast<std::uint32_t>(window.max.x - window.min.x + 1);
        result.image.height = static_cast<std::uint32_t>(window.max.y - window.min.y + 1);
        result.image.rgba.assign(std::size_t{result.image.width} * result.image.height * 4, 0.0f);
        result.envmap = envmapOf(header);

        Imf::FrameBuffer frameBuffer;
        const char* names[4] = {"R", "G", "B", "A"};
        for (std::size_t c = 0; c < 4; ++c) {
            const double fill = c == 3 ? 1.0 : 0.0;  // missing alpha reads as opaque
            frameBuffer.insert(names[c],
                               Imf::Slice::Make(Imf::FLOAT, result.image.rgba.data() + c, window,
                                                4 * sizeof(float), 0, 1, 1, fill));
        }
        file.setFrameBuffer(frameBuffer);
        file.readPixels(window.min.y, window.max.y);
    } catch (const std::exception& e) {
        diagnostics.error(name, "", std::string("cannot read OpenEXR data: ") + e.what());
        return std::nullopt;
    } catch (...) {
        diagnostics.error(name, "", "cannot read OpenEXR data: unknown exception");
        return std::nullopt;
    }
    result.replacedNonFiniteTexels = replaceNonFinite(result.image);
    if (result.replacedNonFiniteTexels > 0) {
        diagnostics.warning(
            name, "",
            std::to_string(result.replacedNonFiniteTexels) +
                " texels had NaN or Inf channels; NaN and -Inf set to 0, +Inf to 65504");
    }
    return result;
}

std::optional<ExrImage> readExrImage(const std::filesystem::path& path, Diagnostics& diagnostics,
                                     const ExrLimits& limits) {
    FileBytes file = readFileBytes(path, limits.maxFileBytes);
    if (!file.error.empty()) {
        diagnostics.error(path.string(), "", file.error);
        return std::nullopt;
    }
    return readExrImageFromMemory(file.bytes, path.string(), diagnostics, limits);
}

}  // namespace candela::content
