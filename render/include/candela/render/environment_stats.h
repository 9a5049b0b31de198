#pragma once
// What building a sky cost and where it came from (--stats "environment"). Apart from
// environment.h so the runtime's stats reach games without Vulkan.
#include <cstdint>
#include <string>

namespace candela::render {

struct EnvironmentBuildStats {
    std::string source;  // the file, or "uniform"
    uint64_t contentHash = 0;
    bool fromCache = false;
    bool fallback = false;      // the file could not be used: neutral uniform sky instead
    double readMs = 0.0;        // reading and hashing the file
    double decodeMs = 0.0;      // OpenEXR decode (0 on a cache hit)
    double precomputeMs = 0.0;  // cube, mips, prefiltering, SH on the device (0 when cached)
    double cacheMs = 0.0;       // writing the cache file, or reading and uploading it
    uint32_t cubeFaceSize = 0;
    uint32_t prefilteredFaceSize = 0;
    uint32_t prefilteredMipCount = 0;
};

}  // namespace candela::render
