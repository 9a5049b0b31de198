#include "candela/render/environment.h"

#include <cstdlib>
#include <cstring>
#include <vector>

#include "candela/content/exr_image.h"
#include "candela/content/file_bytes.h"
#include "candela/render/gpu_context.h"
#include "cpu_clock.h"
#include "ibl/environment_cache.h"
#include "ibl/environment_precompute.h"
#include "vk/image_transfer.h"
#include "vk/sampler.h"

namespace candela::render {

namespace {

using Clock = CpuClock;
constexpr uint32_t kTexelBytes = 8;  // RGBA16F
constexpr VkDeviceSize kShBytes = 9 * 16;

content::EnvironmentMap uniformMap(float radiance) {
    content::EnvironmentMap map;
    map.layout = content::EnvironmentLayout::LatLong;
    map.latLong.width = 64;
    map.latLong.height = 32;
    map.latLong.rgba.assign(64 * 32 * 4, radiance);
    for (size_t i = 3; i < map.latLong.rgba.size(); i += 4)
        map.latLong.rgba[i] = 1.0f;
    return map;
}

}  // namespace

std::filesystem::path defaultEnvironmentCacheDirectory() {
    if (const char* dir = std::getenv("CANDELA_CACHE_DIR"); dir && *dir) return dir;
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) {
        return std::filesystem::path(xdg) / "candela";
    }
    if (const char* home = std::getenv("HOME"); home && *home) {
        return std::filesystem::path(home) / ".cache" / "candela";
    }
    return std::filesystem::temp_directory_path() / "candela-cache";
}

Environment::Environment(GpuContext& context) : context_(context) {
    sampler_ = std::make_unique<Sampler>(context, SamplerDesc{VK_FILTER_LINEAR, true});
}

Environment::~Environment() = default;

VkSampler Environment::sampler() const {
    return sampler_->handle();
}

void Environment::allocate(uint32_t sourceFace) {
    EnvironmentSizes sizes = environmentSizesFor(sourceFace);
    constexpr VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
                                        VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                        VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    cube_ = GpuImage(context_, {VK_FORMAT_R16G16B16A16_SFLOAT, sizes.cubeFaceSize,
                                sizes.cubeFaceSize, sizes.cubeMipCount, true, usage});
    prefiltered_ =
        GpuImage(context_, {VK_FORMAT_R16G16B16A16_SFLOAT, sizes.prefilteredFaceSize,
                            sizes.prefilteredFaceSize, sizes.prefilteredMipCount, true, usage});
    irradianceSh_ = GpuBuffer(context_, kShBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                              MemoryLocation::HostVisible);
    stats_.cubeFaceSize = sizes.cubeFaceSize;
    stats_.prefilteredFaceSize = sizes.prefilteredFaceSize;
    stats_.prefilteredMipCount = sizes.prefilteredMipCount;
}

std::unique_ptr<Environment> Environment::fromMap(GpuContext& context,
                                                  const content::EnvironmentMap& map,
                                                  const std::string& name) {
    std::unique_ptr<Environment> env(new Environment(context));
    env->stats_.source = name;
    env->allocate(sourceCubeFaceSize(map));
    Clock::time_point start = Clock::now();
    precomputeEnvironment(context, map, env->cube_, env->prefiltered_, env->irradianceSh_);
    env->stats_.precomputeMs = millisecondsSince(start);
    return env;
}

std::unique_ptr<Environment> Environment::forDevice(GpuContext& context, uint32_t cubeFaceSize,
                                                    const std::string& name) {
    std::unique_ptr<Environment> env(new Environment(context));
    env->stats_.source = name;
    env->allocate(cubeFaceSize);
    return env;
}

std::unique_ptr<Environment> Environment::uniform(GpuContext& context, float radiance) {
    return fromMap(context, uniformMap(radiance), "uniform");
}

std::unique_ptr<Environment> Environment::load(GpuContext& context,
                                               const std::filesystem::path& exr,
                                               content::Diagnostics& diagnostics,
                                               const EnvironmentCacheOptions& cache) {
    auto fallback = [&](const std::string& problem) {
        diagnostics.error(exr.string(), "",
                          problem + "; using a neutral uniform sky of " +
                              std::to_string(int(kFallbackRadiance)) + " cd/m^2");
        std::unique_ptr<Environment> env = uniform(context, kFallbackRadiance);
        env->stats_.source = exr.string();
        env->stats_.fallback = true;
        return env;
    };

    Clock::time_point start = Clock::now();
    // Type and size are checked before reading: a FIFO, a device or a 20 GB file is a clear
    // error and the fallback sky, never a hang or an allocation failure.
    content::FileBytes file = content::readFileBytes(exr, content::ExrLimits{}.maxFileBytes);
    if (!file.error.empty()) {
        return fallback("cannot read the environment file: " + file.error);
    }
    const std::vector<std::byte>* bytes = &file.bytes;
    uint64_t hash = contentHash(*bytes);
    double readMs = millisecondsSince(start);

    std::filesystem::path directory =
        cache.directory.empty() ? defaultEnvironmentCacheDirectory() : cache.directory;
    std::filesystem::path entryPath = environmentCachePath(directory, hash);
    if (cache.enabled) {
        start = Clock::now();
        std::string problem;
        if (std::optional<CachedEnvironment> entry = readCachedEnvironment(entryPath, problem)) {
            std::unique_ptr<Environment> env(new Environment(context));
            env->allocate(entry->sizes.cubeFaceSize);
            if (imageByteSize(env->cube_, kTexelBytes) == entry->cube.size() &&
                imageByteSize(env->prefiltered_, kTexelBytes) == entry->prefiltered.size()) {
                writeImage(context, env->cube_, kTexelBytes, entry->cube.data());
                writeImage(context, env->prefiltered_, kTexelBytes, entry->prefiltered.data());
                std::memcpy(env->irradianceSh_.mapped(), entry->irradianceSh.data(), kShBytes);
                env->stats_.source = exr.string();
                env->stats_.contentHash = hash;
                env->stats_.fromCache = true;
                env->stats_.readMs = readMs;
                env->stats_.cacheMs = millisecondsSince(start);
                return env;
            }
            problem = "image sizes do not match";
        }
        if (!problem.empty()) {
            diagnostics.warning(entryPath.string(), "",
                                "ignoring cache entry (" + problem + "); recomputing");
        }
    }

    start = Clock::now();
    std::optional<content::EnvironmentMap> map;
    if (std::optional<content::ExrImage> image =
            content::readExrImageFromMemory(*bytes, exr.string(), diagnostics)) {
        map = content::environmentFromExr(std::move(*image), exr.string(), diagnostics);
    }
    if (!map) return fallback("cannot use the environment file (see the messages above)");
    double decodeMs = millisecondsSince(start);

    std::unique_ptr<Environment> env = fromMap(context, *map, exr.string());
    env->stats_.contentHash = hash;
    env->stats_.readMs = readMs;
    env->stats_.decodeMs = decodeMs;
    if (cache.enabled) {
        start = Clock::now();
        CachedEnvironment entry;
        entry.sizes = environmentSizesFor(env->stats_.cubeFaceSize);
        entry.cube =
            readImage(context, env->cube_, kTexelBytes, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
        entry.prefiltered = readImage(context, env->prefiltered_, kTexelBytes,
                                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
        entry.irradianceSh.resize(kShBytes);
        std::memcpy(entry.irradianceSh.data(), env->irradianceSh_.mapped(), kShBytes);
        if (std::string e = writeCachedEnvironment(entryPath, entry); !e.empty()) {
            diagnostics.warning(entryPath.string(), "", "environment cache not written: " + e);
        }
        env->stats_.cacheMs = millisecondsSince(start);
    }
    return env;
}

}  // namespace candela::render
