#pragma once
// Image-based lighting for one HDR environment (Karis 2013, "Real Shading in Unreal Engine 4",
// "Image-Based Lighting", eq. 6-8): the environment cube with mips (sky background, reference
// mode), the GGX-prefiltered radiance cube with one roughness per mip (split sum), and order-2
// spherical-harmonic irradiance (diffuse). Built on the device from an OpenEXR file; the results
// are cached on disk under the file's content hash, so a second run reads them instead of
// recomputing.
//
//   content::Diagnostics diagnostics;
//   resources.setEnvironment(Environment::load(context, "sky.exr", diagnostics));
//   // A bad file leaves a message in diagnostics and a neutral uniform sky.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "candela/content/diagnostics.h"
#include "candela/content/environment_map.h"
#include "candela/render/environment_stats.h"
#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_image.h"

namespace candela::render {

class GpuContext;
class Sampler;

struct EnvironmentCacheOptions {
    std::filesystem::path directory;  // empty: defaultEnvironmentCacheDirectory()
    bool enabled = true;
};

// $CANDELA_CACHE_DIR, else $XDG_CACHE_HOME/candela, else $HOME/.cache/candela, else a
// folder under the system temp directory.
std::filesystem::path defaultEnvironmentCacheDirectory();

class Environment {
public:
    // Radiance of the neutral sky used when a file cannot be loaded, in cd/m^2 (an overcast
    // sky's order of magnitude).
    static constexpr float kFallbackRadiance = 1000.0f;

    // Never null: a file that cannot be used yields the neutral sky and a diagnostic naming it.
    static std::unique_ptr<Environment> load(GpuContext& context, const std::filesystem::path& exr,
                                             content::Diagnostics& diagnostics,
                                             const EnvironmentCacheOptions& cache = {});
    static std::unique_ptr<Environment> fromMap(GpuContext& context,
                                                const content::EnvironmentMap& map,
                                                const std::string& name);
    // The same radiance from every direction (the neutral sky, and the white furnace).
    static std::unique_ptr<Environment> uniform(GpuContext& context, float radiance);

    // Images and SH buffer of a `cubeFaceSize` cube (a power of two, 16..512) with undefined
    // contents, for a sky the device draws itself (the atmosphere); its maker fills them and
    // leaves the cubes in SHADER_READ_ONLY_OPTIMAL before anything samples them.
    static std::unique_ptr<Environment> forDevice(GpuContext& context, uint32_t cubeFaceSize,
                                                  const std::string& name);

    ~Environment();
    Environment(const Environment&) = delete;
    Environment& operator=(const Environment&) = delete;

    // Both cubes are RGBA16F in SHADER_READ_ONLY_OPTIMAL; sampled with sampler().
    const GpuImage& cube() const { return cube_; }
    const GpuImage& prefiltered() const { return prefiltered_; }
    // 9 vec4: SH coefficients of irradiance (already convolved with the clamped cosine).
    const GpuBuffer& irradianceSh() const { return irradianceSh_; }
    VkSampler sampler() const;
    const EnvironmentBuildStats& stats() const { return stats_; }

private:
    explicit Environment(GpuContext& context);
    void allocate(uint32_t cubeFaceSize);

    GpuContext& context_;
    GpuImage cube_;
    GpuImage prefiltered_;
    GpuBuffer irradianceSh_;
    std::unique_ptr<Sampler> sampler_;
    EnvironmentBuildStats stats_;
};

}  // namespace candela::render
