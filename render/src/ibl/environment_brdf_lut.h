#pragma once
// The environment BRDF LUT of eq. 8: (scale, bias) of F0 over (NoV, roughness),
// R16G16B16A16_UNORM: .rg with Schlick-Smith visibility (the UE4 BRDF), .ba with height-
// correlated Smith (the energy-conserving BRDF, which also reads its scale + bias as the
// directional albedo E_ss for multiple scattering). Computed once on the device when the first
// environment is lit, or with the first frame of the energy-conserving BRDF. The environment
// never enters it, so one LUT serves every sky. loadOrBuild() keeps its texels in the
// environment cache folder (and in memory for the process), so only the first run builds it.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_image.h"

namespace candela::render {

class GpuContext;
class Sampler;

class EnvironmentBrdfLut {
public:
    static constexpr uint32_t kSize = 128;
    // Hammersley samples per texel: deterministic, and within 2e-3 of a double-precision
    // integration at every texel (tests/render/ibl_tests.cpp).
    static constexpr uint32_t kSampleCount = 1024;

    // Bump when environment_brdf_lut.comp's output changes for the same SPIR-V (the SPIR-V's
    // hash is part of the cache key too, so a shader edit never reuses a stale file).
    static constexpr uint32_t kCacheVersion = 1;

    enum class Source { Built, DiskCache, ProcessCache };

    // Always builds on the device (tests and benchmarks of the build itself).
    explicit EnvironmentBrdfLut(GpuContext& context);
    // The texels from this process's earlier LUT for the same folder, else from the cache
    // file in `cacheDirectory`, else built and written there. A missing, corrupt or
    // unwritable cache adds a line to `warnings` (never a failure); an empty directory
    // disables the disk cache.
    static std::unique_ptr<EnvironmentBrdfLut> loadOrBuild(
        GpuContext& context, const std::filesystem::path& cacheDirectory,
        std::vector<std::string>& warnings);
    // The cache file for this build of the shader, size and format.
    static std::filesystem::path cachePath(const std::filesystem::path& cacheDirectory);
    ~EnvironmentBrdfLut();
    EnvironmentBrdfLut(const EnvironmentBrdfLut&) = delete;
    EnvironmentBrdfLut& operator=(const EnvironmentBrdfLut&) = delete;

    const GpuImage& image() const { return image_; }  // SHADER_READ_ONLY_OPTIMAL
    VkSampler sampler() const;
    // The texels as computed, two uints each: packUnorm2x16(scale, bias) with Schlick-Smith
    // then with height-correlated Smith; row = roughness, column = NoV.
    const uint32_t* packedTexels() const { return static_cast<const uint32_t*>(texels_.mapped()); }
    uint32_t packedSchlick(uint32_t texel) const { return packedTexels()[2 * texel]; }
    uint32_t packedCorrelated(uint32_t texel) const { return packedTexels()[2 * texel + 1]; }
    double buildMs() const { return buildMs_; }  // building, or reading and uploading
    Source source() const { return source_; }
    const char* sourceName() const;  // "built", "disk_cache", "process_cache"

private:
    EnvironmentBrdfLut(GpuContext& context, const uint32_t* cachedTexels, Source source);
    void copyTexelsToImage(VkCommandBuffer cmd);
    static constexpr size_t kTexelBytes = size_t(kSize) * kSize * 8;

    GpuImage image_;
    GpuBuffer texels_;
    std::unique_ptr<Sampler> sampler_;
    double buildMs_ = 0.0;
    Source source_ = Source::Built;
};

}  // namespace candela::render
